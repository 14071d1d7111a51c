// How one run of the line is set up and stepped: which parcels enter the drying tube (those
// that leave the line at the wanted rows, and those that leave the tube then), how the solver is
// told its tolerances, and how the states and their sensitivities pass from the tube to the
// conveyor's top layer, through the winnower inlet mix (Eqs. 15–16) and the winnower, to the
// outlet and the proxies of SimulationResult. The rates the solver integrates are in
// SectionRightHandSides.cpp; the outlet as the meter reads it, in MeasuredOutlet.cpp.

#include "physics/SectionRates.h"
#include "physics/simulator/LineSimulatorInternal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace drytwin::physics::simulator {

namespace {

/// True when the time index is uniform to 1e-9 of its step.
bool isUniform(const std::vector<double>& t) {
    const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (std::abs(t[i] - (t.front() + static_cast<double>(i) * dt)) > 1e-9 * dt) {
            return false;
        }
    }
    return true;
}

SectionContext makeContext(const LineInputs& in, const ParameterSet& p, const properties::ModelSwitches& sw,
                           const std::vector<double>& entry, bool uniform) {
    SectionContext c{&in, &p, &sw, &entry, std::vector<std::size_t>(entry.size(), 0)};
    c.uniform = uniform;
    c.t0 = in.timeS.front();
    c.invDt = static_cast<double>(in.timeS.size() - 1) / (in.timeS.back() - in.timeS.front());
    return c;
}

IntegratorSettings settingsFor(const SimulationOptions& o, int states) {
    IntegratorSettings s;
    s.reference = o.reference;
    s.maxSteps = o.maxStepsPerSection;
    s.relTol = o.relTol;
    // Absolute tolerances per state (moisture in kg/kg, temperature in K), shrinking with the
    // relative tolerance.
    const double atolX = std::min(1e-6, o.relTol * 1e-2);
    const double atolT = std::min(1e-2, o.relTol * 1e2);
    s.absTol =
        states == 2 ? std::vector<double>{atolX, atolT} : std::vector<double>{atolX, atolT, atolX, atolT};
    return s;
}

} // namespace

Expected<SimulationResult> simulateCore(const LineInputs& in, const ParameterSet& params,
                                        const SimulationOptions& o, const std::vector<std::size_t>& rows,
                                        const std::vector<Param>& odeSens,
                                        const std::vector<std::uint8_t>& outletOnly) {
    SimulationResult res;
    res.rows = rows;
    const bool uniform = isUniform(in.timeS);
    const std::size_t n = rows.size();
    ParameterSet p = params; // CVODES perturbs this copy in place
    const double tauH = p[Param::tau_HDT];
    const double tauC = p[Param::tau_conv] + p[Param::dtau_conv]; // transport_delay_error
    const double tW = p[Param::t_W];

    SensitivitySpec spec;
    const bool withSens = !odeSens.empty();
    const std::size_t ns = odeSens.size();
    for (Param q : odeSens) {
        spec.plist.push_back(static_cast<int>(q));
        const double v = std::abs(p[q]);
        spec.pbar.push_back(v > 0 ? v : 1.0);
    }
    spec.params = p.data();

    // Tube: the parcel that leaves the line at row k (set A) and the one that leaves the tube at
    // row k (set B). With delays that are whole sample steps most set-A parcels are set-B parcels
    // of earlier rows, so equal entry times share one integration.
    std::vector<double> entryTube;
    entryTube.reserve(2 * n);
    constexpr std::size_t kNoParcel = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> tubeOfA(n);
    std::vector<std::size_t> tubeOfB(n, kNoParcel);
    const auto wantsTubeOutlet = [&](std::size_t j) { return outletOnly.empty() || !outletOnly[j]; };
    {
        std::vector<std::pair<double, std::size_t>> wanted; // (entry time, slot: j for A, n + j for B)
        wanted.reserve(2 * n);
        for (std::size_t j = 0; j < n; ++j) {
            const double tOut = in.timeS[rows[j]];
            wanted.emplace_back(tOut - (tauH + tauC + tW), j);
            if (wantsTubeOutlet(j)) {
                wanted.emplace_back(tOut - tauH, n + j);
            }
        }
        std::sort(wanted.begin(), wanted.end());
        for (const auto& [t, slot] : wanted) {
            if (entryTube.empty() || t - entryTube.back() > 1e-9) {
                entryTube.push_back(t);
            }
            (slot < n ? tubeOfA[slot] : tubeOfB[slot - n]) = entryTube.size() - 1;
        }
    }
    const std::size_t nTube = entryTube.size();
    std::vector<double> y(2 * nTube);
    for (std::size_t j = 0; j < nTube; ++j) {
        y[2 * j] = interpolate(in.timeS, in.xInDb, entryTube[j]);
        y[2 * j + 1] = interpolate(in.timeS, in.tInK, entryTube[j]);
    }
    std::vector<std::vector<double>> yS(ns, std::vector<double>(2 * nTube, 0.0));
    std::vector<double> xeSeries;
    const bool xeMoves = std::any_of(odeSens.begin(), odeSens.end(), [](Param q) {
        return q == Param::theta_xe1 || q == Param::theta_xe2 || q == Param::theta_xe3;
    });
    if (!xeMoves) {
        xeSeries.resize(in.size());
        for (std::size_t k = 0; k < in.size(); ++k) {
            xeSeries[k] = properties::equilibriumMoisture(in.tAmbK[k], in.rhAmb[k], p);
        }
    }
    // One section: every parcel (entry times, states) integrated over the section's duration.
    using Evaluate = bool (*)(const void*, double, std::size_t, std::size_t, const double*, double*);
    auto runSection = [&](Evaluate evaluate, const std::vector<double>& entry, int states, double duration,
                          std::vector<double>& state, std::vector<std::vector<double>>& sens,
                          const char* name) {
        SectionContext ctx = makeContext(in, p, o.switches, entry, uniform);
        ctx.xMix = res.proxyXMixDb.data();
        ctx.tMixK = res.proxyTMixK.data();
        ctx.xeSeries = xeMoves ? nullptr : &xeSeries;
        const ParcelRhs rhs{&ctx, evaluate, entry.size(), states};
        return integrateParcels(rhs, state, duration, settingsFor(o, states), withSens ? &spec : nullptr,
                                withSens ? &sens : nullptr, name, &res.stats);
    };
    if (auto st = runSection(tubeEval, entryTube, 2, tauH, y, yS, "drying tube"); !st) {
        return st.error();
    }
    res.xHdtDb.resize(n);
    res.tHdtK.resize(n);
    res.proxyXHdtDb.resize(n);
    res.proxyTHdtK.resize(n);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t j = 0; j < n; ++j) {
        res.proxyXHdtDb[j] = y[2 * tubeOfA[j]];
        res.proxyTHdtK[j] = y[2 * tubeOfA[j] + 1];
        const bool b = tubeOfB[j] != kNoParcel;
        res.xHdtDb[j] = b ? y[2 * tubeOfB[j]] : nan;
        res.tHdtK[j] = b ? y[2 * tubeOfB[j] + 1] : nan;
    }
    for (std::size_t q = 0; q < ns; ++q) {
        OutputSensitivity os;
        os.param = odeSens[q];
        os.dXHdt.resize(n);
        os.dTHdt.resize(n);
        for (std::size_t j = 0; j < n; ++j) {
            const bool b = tubeOfB[j] != kNoParcel;
            os.dXHdt[j] = b ? yS[q][2 * tubeOfB[j]] : nan;
            os.dTHdt[j] = b ? yS[q][2 * tubeOfB[j] + 1] : nan;
        }
        res.sensitivities.push_back(std::move(os));
    }

    // Conveyor: the top layer of set A.
    std::vector<double> entryConv(n);
    std::vector<double> yc(2 * n);
    std::vector<std::vector<double>> ySc(ns, std::vector<double>(2 * n));
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t a = tubeOfA[j];
        entryConv[j] = entryTube[a] + tauH;
        yc[2 * j] = y[2 * a];
        yc[2 * j + 1] = y[2 * a + 1];
        for (std::size_t q = 0; q < ns; ++q) {
            ySc[q][2 * j] = yS[q][2 * a];
            ySc[q][2 * j + 1] = yS[q][2 * a + 1];
        }
    }
    if (auto st = runSection(conveyorEval, entryConv, 2, tauC, yc, ySc, "conveyor"); !st) {
        return st.error();
    }

    // Winnower inlet mix, Eqs. 15–16, and its Jacobian for the sensitivities (the mix is
    // algebraic, so central differences are accurate to ~1e-9 here).
    std::vector<double> entryWin(n);
    // With sensitivities the mix rides along as two constant states (so that its sensitivities
    // reach Eq. 18); without, it is read from the proxies, which halves the winnower's system.
    const std::size_t wm = withSens ? 4 : 2;
    std::vector<double> yw(wm * n);
    std::vector<std::vector<double>> ySw(ns, std::vector<double>(4 * n));
    res.proxyXConvDb.resize(n);
    res.proxyTConvK.resize(n);
    res.proxyXMixDb.resize(n);
    res.proxyTMixK.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
        const double xc = yc[2 * j];
        const double tc = yc[2 * j + 1];
        const double xh = y[2 * tubeOfA[j]];
        const double th = y[2 * tubeOfA[j] + 1];
        const MixState mix = winnowerInletMix(xc, tc, xh, th, p, o.switches);
        entryWin[j] = entryConv[j] + tauC;
        res.proxyXConvDb[j] = xc;
        res.proxyTConvK[j] = tc;
        res.proxyXMixDb[j] = mix.xDb;
        res.proxyTMixK[j] = mix.tK;
        yw[wm * j] = mix.xDb;
        yw[wm * j + 1] = mix.tK;
        if (!withSens) {
            continue;
        }
        yw[4 * j + 2] = mix.xDb;
        yw[4 * j + 3] = mix.tK;
        const double in4[4] = {xc, tc, xh, th};
        double jac[2][4];
        for (int a = 0; a < 4; ++a) {
            double up[4] = {in4[0], in4[1], in4[2], in4[3]};
            double dn[4] = {in4[0], in4[1], in4[2], in4[3]};
            const double h = 1e-6 * std::max(1.0, std::abs(in4[a]));
            up[a] += h;
            dn[a] -= h;
            const MixState mu = winnowerInletMix(up[0], up[1], up[2], up[3], p, o.switches);
            const MixState md = winnowerInletMix(dn[0], dn[1], dn[2], dn[3], p, o.switches);
            jac[0][a] = (mu.xDb - md.xDb) / (2 * h);
            jac[1][a] = (mu.tK - md.tK) / (2 * h);
        }
        for (std::size_t q = 0; q < ns; ++q) {
            const double d4[4] = {ySc[q][2 * j], ySc[q][2 * j + 1], yS[q][2 * tubeOfA[j]],
                                  yS[q][2 * tubeOfA[j] + 1]};
            double dx = 0;
            double dt = 0;
            for (int a = 0; a < 4; ++a) {
                dx += jac[0][a] * d4[a];
                dt += jac[1][a] * d4[a];
            }
            // Direct dependence of the mix on the parameter (β_top, θ_Cp1, θ_Cp2).
            ParameterSet pp = p;
            const double v = p[odeSens[q]];
            const double h = 1e-6 * std::max(1e-3, std::abs(v));
            pp[odeSens[q]] = v + h;
            const MixState mu = winnowerInletMix(xc, tc, xh, th, pp, o.switches);
            pp[odeSens[q]] = v - h;
            const MixState md = winnowerInletMix(xc, tc, xh, th, pp, o.switches);
            dx += (mu.xDb - md.xDb) / (2 * h);
            dt += (mu.tK - md.tK) / (2 * h);
            ySw[q][4 * j] = dx;
            ySw[q][4 * j + 1] = dt;
            ySw[q][4 * j + 2] = dx;
            ySw[q][4 * j + 3] = dt;
        }
    }

    res.xOutDb.resize(n);
    res.tOutK.resize(n);
    if (o.winnower == WinnowerForm::Transient) {
        if (auto st = runSection(withSens ? winnowerEvalWithMixStates : winnowerEval, entryWin,
                                 static_cast<int>(wm), tW, yw, ySw, "winnower");
            !st) {
            return st.error();
        }
        for (std::size_t j = 0; j < n; ++j) {
            res.xOutDb[j] = yw[wm * j];
            res.tOutK[j] = yw[wm * j + 1];
        }
        for (std::size_t q = 0; q < ns; ++q) {
            auto& os = res.sensitivities[q];
            os.dXOut.resize(n);
            os.dTOut.resize(n);
            for (std::size_t j = 0; j < n; ++j) {
                os.dXOut[j] = ySw[q][4 * j];
                os.dTOut[j] = ySw[q][4 * j + 1];
            }
        }
    } else {
        for (std::size_t j = 0; j < n; ++j) {
            const double xm = res.proxyXMixDb[j];
            const double tm = res.proxyTMixK[j];
            const AmbientEnvironment env{interpolate(in.timeS, in.tAmbK, entryWin[j]),
                                         interpolate(in.timeS, in.rhAmb, entryWin[j]), 0.0};
            const double xOut = winnowerTerminalMoisture(xm, tm, env, p); // Eq. (17)
            // Eq. (19) over t_W as one explicit step with the evaporated mass of Eq. 17.
            const auto r = winnowerRates(xm, tm, 0.0, xm, tm, env, p, o.switches);
            res.xOutDb[j] = xOut;
            res.tOutK[j] = tm + (r.heatIn * tW - r.vapourEnthalpy * (xm - xOut)) / r.heatCapacity;
        }
    }
    return res;
}

} // namespace drytwin::physics::simulator
