// How the outlet the line predicts becomes the outlet as measured: the line's outlet mixing
// (tau_mix) and the moisture meter's lag (tau_meter) act on the outlet's history, which comes from
// the wanted rows, a short raw tail before each and, between them, a coarse grid on averaged
// inputs; then the meter's offset (X_meter_offset) in % wb. Each applies to the prediction and to
// its sensitivities, and the outlet-only parameters' own sensitivities come from the same history.
// Also the finite differences that LineSimulator.cpp uses for the residence times.

#include "common/FirstOrderLag.h"
#include "common/MovingAverage.h"
#include "common/Units.h"
#include "physics/simulator/LineSimulatorInternal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace drytwin::physics::simulator {

namespace {

/// Each input column averaged over a centred window of @p windowS (time-based, per batch).
LineInputs boxSmoothed(const LineInputs& in, double windowS) {
    LineInputs out = in;
    const auto& t = in.timeS;
    for (auto [src, dst] : {std::pair{&in.tHotK, &out.tHotK},
                            {&in.xInDb, &out.xInDb},
                            {&in.tInK, &out.tInK},
                            {&in.tAmbK, &out.tAmbK},
                            {&in.rhAmb, &out.rhAmb},
                            {&in.feedKgPerS, &out.feedKgPerS},
                            {&in.airSpeedMPerS, &out.airSpeedMPerS}}) {
        if (src->size() == t.size()) {
            *dst = centredMovingAverage(t, *src, windowS);
        }
    }
    return out;
}

/// The moisture_meter_offset extension: a constant offset in % wb on the predicted X_out and,
/// by the chain rule through wet basis, on its sensitivities.
void applyMeterOffset(SimulationResult& res, double offsetPct, const std::vector<double>& timeS,
                      double onsetS) {
    for (std::size_t j = 0; j < res.xOutDb.size(); ++j) {
        if (timeS[res.rows[j]] < onsetS) {
            continue;
        }
        const double x = res.xOutDb[j];
        const double wet = units::dryToWetPct(x) + offsetPct;
        const double shifted = units::wetPctToDry(wet);
        // Chain rule through wet basis: dX'/dX = (dX'/dw)(dw/dX).
        const double slope = (100.0 / ((100.0 - wet) * (100.0 - wet))) * (100.0 / ((1 + x) * (1 + x)));
        res.xOutDb[j] = shifted;
        for (auto& sens : res.sensitivities) {
            sens.dXOut[j] *= slope;
        }
    }
}

/// ∂X_out/∂X_meter_offset of the reading after the offset: dX/dw = 100/(100 − w)² per % wb from
/// the onset on, 0 before it.
OutputSensitivity meterOffsetSensitivity(const SimulationResult& res, const std::vector<double>& timeS,
                                         double onsetS) {
    const std::size_t n = res.xOutDb.size();
    OutputSensitivity os{Param::X_meter_offset, std::vector<double>(n, 0.0), std::vector<double>(n, 0.0),
                         std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
    for (std::size_t j = 0; j < n; ++j) {
        if (timeS[res.rows[j]] >= onsetS) {
            const double wet = units::dryToWetPct(res.xOutDb[j]);
            os.dXOut[j] = 100.0 / ((100.0 - wet) * (100.0 - wet));
        }
    }
    return os;
}

/// The meter's offset on a simulated outlet reading (from the onset on), and the offset's own
/// sensitivity where it is asked for.
void readThroughMeterOffset(SimulationResult& res, double offsetPct, bool withSensitivity,
                            const std::vector<double>& timeS, double onsetS) {
    if (offsetPct != 0) {
        applyMeterOffset(res, offsetPct, timeS, onsetS);
    }
    if (withSensitivity) {
        res.sensitivities.push_back(meterOffsetSensitivity(res, timeS, onsetS));
    }
}

} // namespace

DifferenceStep differenceStep(double v, double lower) {
    const double h = 1e-3 * std::max(1.0, std::abs(v));
    const bool oneSided = v - h < lower;
    return {v + h, oneSided ? v : v - h, oneSided ? h : 2 * h};
}

std::vector<double> dividedDifference(const std::vector<double>& up, const std::vector<double>& down,
                                      double span) {
    std::vector<double> d(up.size());
    for (std::size_t j = 0; j < d.size(); ++j) {
        d[j] = (up[j] - down[j]) / span;
    }
    return d;
}

Expected<SimulationResult> simulateMeasured(const LineInputs& measured, const ParameterSet& params,
                                            const SimulationOptions& o, const std::vector<std::size_t>& rows,
                                            const std::vector<Param>& odeSens,
                                            const std::vector<Param>& outputSens) {
    const auto corrected = correctedInputs(measured, params);
    const LineInputs& in = corrected ? *corrected : measured;
    const double tauMeter = params[Param::tau_meter];
    const double tauMix = params[Param::tau_mix];
    const double offsetPct = params[Param::X_meter_offset];
    const double onsetS = in.timeS.front() + in.onsetS(params[Param::t_onset]);
    const auto wants = [&](Param q) {
        return std::find(outputSens.begin(), outputSens.end(), q) != outputSens.end();
    };
    const bool lagged = tauMeter > 0 || tauMix > 0;
    if ((!lagged && !wants(Param::tau_meter) && !wants(Param::tau_mix)) || rows.empty()) {
        auto res = simulateCore(in, params, o, rows, odeSens);
        if (res) {
            readThroughMeterOffset(*res, offsetPct, wants(Param::X_meter_offset), in.timeS, onsetS);
        }
        return res;
    }
    // The lag needs the output's history from the first row on. Between the wanted rows it comes
    // from a grid of meterGridS on inputs averaged over the same span: computing every row costs
    // as many parcels as the whole batch (44× the rows of a discovery fit), and the meter's own
    // lag averages what happens within a grid step. Sampled raw, the sample-to-sample noise of
    // the inputs would alias into the filtered value; averaged, the grid stays within 0.0015 % wb
    // rms of every row (tests/engine/physics). The grid does not depend on τ, so the loss stays
    // smooth in τ for the fits. meterGridS = 0, or every row wanted: every row, exact.
    std::vector<std::size_t> order(rows.size()); // wanted rows by time
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return rows[a] < rows[b]; });
    const std::size_t last = rows[order.back()];
    bool everyRow = true;
    for (std::size_t j = 0; j < rows.size() && everyRow; ++j) {
        everyRow = rows[j] == j;
    }
    // Without a lag (a lag's sensitivity at 0 alone) the history that counts is the wanted row and
    // the sample before it: a lag of the difference step (1 ms) forgets anything older (e^-1000 a
    // second back), so the grid is not run.
    const bool rawTailOnly = !lagged && !everyRow;
    const bool onGrid = o.meterGridS > 0 && !everyRow && !rawTailOnly;
    // The history: the grid on averaged inputs, and the wanted row and the one before it on the
    // raw inputs. So the filtered value tends to the raw output as τ → 0 (the score test's
    // difference at τ = 0 is then −dX/dt of the raw output); a longer raw tail measured no more
    // accurate (tests/engine/physics).
    constexpr double kRawTailS = 2;
    enum : std::uint8_t { kNone = 0, kGrid = 1, kRaw = 2 };
    std::vector<std::uint8_t> kind(last + 1, onGrid || rawTailOnly ? kNone : kRaw);
    if (onGrid || rawTailOnly) {
        double lastGridTime = -std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j <= last && onGrid; ++j) {
            if (in.timeS[j] - lastGridTime >= o.meterGridS - 1e-9) {
                kind[j] = kGrid;
                lastGridTime = in.timeS[j];
            }
        }
        double nextWantedTime = std::numeric_limits<double>::infinity();
        std::size_t pending = order.size(); // wanted rows at or after j are order[pending..]
        for (std::size_t j = last + 1; j-- > 0;) {
            while (pending > 0 && rows[order[pending - 1]] >= j) {
                nextWantedTime = in.timeS[rows[order[--pending]]];
            }
            if (nextWantedTime - in.timeS[j] < kRawTailS - 1e-9) {
                kind[j] = kRaw;
            }
        }
        for (std::size_t r : rows) {
            if (rawTailOnly && r > 0) {
                kind[r - 1] = kRaw; // the sample before, however far back
            }
        }
    }
    std::vector<std::size_t> historyRows, rawRows, gridRows;
    std::vector<std::uint8_t> historyKind;
    std::vector<std::size_t> historyIndex; // into rawRows or gridRows
    for (std::size_t j = 0; j <= last; ++j) {
        if (kind[j] != kNone) {
            historyRows.push_back(j);
            historyKind.push_back(kind[j]);
            auto& list = kind[j] == kRaw ? rawRows : gridRows;
            historyIndex.push_back(list.size());
            list.push_back(j);
        }
    }
    // Only the wanted rows need the tube's outlet; the raw tail before each and the grid are
    // there for the outlet's history.
    std::vector<std::uint8_t> tailOnly(rawRows.size(), 1);
    for (std::size_t r : rows) {
        tailOnly[static_cast<std::size_t>(std::lower_bound(rawRows.begin(), rawRows.end(), r) -
                                          rawRows.begin())] = 0;
    }
    auto raw = simulateCore(in, params, o, rawRows, odeSens, tailOnly);
    if (!raw) {
        return raw;
    }
    // Without a lag the rate parameters' outlet sensitivities are the wanted rows' own, so the
    // grid, there only for the lags' differences, is run without them.
    std::optional<Expected<SimulationResult>> grid;
    if (!gridRows.empty()) {
        grid.emplace(simulateCore(boxSmoothed(in, o.meterGridS), params, o, gridRows,
                                  lagged ? odeSens : std::vector<Param>{},
                                  std::vector<std::uint8_t>(gridRows.size(), 1)));
        if (!*grid) {
            return grid->error();
        }
    }
    const auto historyOf = [&](auto member) {
        std::vector<double> u(historyRows.size());
        for (std::size_t h = 0; h < u.size(); ++h) {
            u[h] = member(historyKind[h] == kRaw ? *raw : grid->value())[historyIndex[h]];
        }
        return u;
    };
    std::vector<double> historyTimeS(historyRows.size());
    for (std::size_t h = 0; h < historyRows.size(); ++h) {
        historyTimeS[h] = in.timeS[historyRows[h]];
    }
    // Exact first-order response to an input linear between history points: as τ → 0 it tends to
    // the input minus τ times its slope, so the sensitivity at τ = 0 is −dX/dt, not 0.
    const auto lagOver = [&](const std::vector<double>& u, double tau) {
        return lagOfPiecewiseLinear(historyTimeS, u, tau);
    };
    // The line's outlet mixing acts on both outlet channels; the meter's lag on top of it, on X_out.
    const auto xOutHistory = historyOf([](const SimulationResult& r) -> const auto& { return r.xOutDb; });
    const auto tOutHistory = historyOf([](const SimulationResult& r) -> const auto& { return r.tOutK; });
    const auto xOutMixed = lagOver(xOutHistory, tauMix);
    const auto tOutMixed = lagOver(tOutHistory, tauMix);
    std::vector<std::vector<double>> sensXMixed, sensTMixed;
    for (std::size_t q = 0; q < raw->sensitivities.size() && lagged; ++q) {
        sensXMixed.push_back(lagOver(
            historyOf([q](const SimulationResult& r) -> const auto& { return r.sensitivities[q].dXOut; }),
            tauMix));
        sensTMixed.push_back(lagOver(
            historyOf([q](const SimulationResult& r) -> const auto& { return r.sensitivities[q].dTOut; }),
            tauMix));
    }
    SimulationResult res = std::move(*raw);
    std::vector<std::size_t> atRaw(rows.size()), atHistory(rows.size());
    for (std::size_t j = 0; j < rows.size(); ++j) {
        atRaw[j] = static_cast<std::size_t>(std::lower_bound(rawRows.begin(), rawRows.end(), rows[j]) -
                                            rawRows.begin());
        atHistory[j] = static_cast<std::size_t>(
            std::lower_bound(historyRows.begin(), historyRows.end(), rows[j]) - historyRows.begin());
    }
    const auto pick = [&](std::vector<double>& v) {
        std::vector<double> out(rows.size());
        for (std::size_t j = 0; j < rows.size(); ++j) {
            out[j] = v[atRaw[j]];
        }
        v = std::move(out);
    };
    const auto atWanted = [&](const std::vector<double>& history) {
        std::vector<double> out(rows.size());
        for (std::size_t j = 0; j < rows.size(); ++j) {
            out[j] = history[atHistory[j]];
        }
        return out;
    };
    // Before the onset the meter reads without its lag (the mixed outlet at the wanted rows).
    const auto meterReading = [&](const std::vector<double>& mixedHistory, double tau) {
        auto out = atWanted(lagOver(mixedHistory, tau));
        if (tau > 0 && onsetS > in.timeS.front()) {
            const auto mixed = atWanted(mixedHistory);
            for (std::size_t j = 0; j < rows.size(); ++j) {
                if (in.timeS[rows[j]] < onsetS) {
                    out[j] = mixed[j];
                }
            }
        }
        return out;
    };
    for (std::size_t q = 0; q < res.sensitivities.size(); ++q) {
        auto& sens = res.sensitivities[q];
        if (lagged) {
            sens.dXOut = meterReading(sensXMixed[q], tauMeter);
            sens.dTOut = atWanted(sensTMixed[q]);
        } else {
            pick(sens.dXOut);
            pick(sens.dTOut);
        }
        pick(sens.dXHdt);
        pick(sens.dTHdt);
    }
    for (auto* v : {&res.xHdtDb, &res.tHdtK, &res.proxyXHdtDb, &res.proxyTHdtK, &res.proxyXConvDb,
                    &res.proxyTConvK, &res.proxyXMixDb, &res.proxyTMixK}) {
        pick(*v);
    }
    res.xOutDb = meterReading(xOutMixed, tauMeter);
    res.tOutK = atWanted(tOutMixed);
    const auto zeros = std::vector<double>(rows.size(), 0.0);
    if (wants(Param::tau_mix)) {
        const auto s = differenceStep(tauMix, properties::info(Param::tau_mix).lower);
        res.sensitivities.push_back(
            {Param::tau_mix,
             dividedDifference(meterReading(lagOver(xOutHistory, s.up), tauMeter),
                               meterReading(lagOver(xOutHistory, s.down), tauMeter), s.span),
             dividedDifference(atWanted(lagOver(tOutHistory, s.up)), atWanted(lagOver(tOutHistory, s.down)),
                               s.span),
             zeros, zeros});
    }
    if (wants(Param::tau_meter)) {
        const auto s = differenceStep(tauMeter, properties::info(Param::tau_meter).lower);
        res.sensitivities.push_back(
            {Param::tau_meter,
             dividedDifference(meterReading(xOutMixed, s.up), meterReading(xOutMixed, s.down), s.span), zeros,
             zeros, zeros});
    }
    res.rows = rows;
    readThroughMeterOffset(res, offsetPct, wants(Param::X_meter_offset), in.timeS, onsetS);
    return res;
}

} // namespace drytwin::physics::simulator
