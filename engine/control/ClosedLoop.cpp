#include "control/ClosedLoop.h"

#include "common/Parallel.h"
#include "common/Units.h"
#include "plant/PlantLine.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

namespace drytwin::control {

namespace {

double median(std::vector<double> v) {
    if (v.empty()) {
        return 0;
    }
    const auto mid = v.begin() + static_cast<long>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

/// Value of a scenario input at time t of the scored part: the initial level moved by the
/// steps and ramps up to t.
double levelAt(const Scenario& s, ScenarioInput input, double initial, double t) {
    double level = initial;
    for (const auto& c : s.inputChanges) {
        if (c.input != input || t < c.atS) {
            continue;
        }
        const double from = level;
        const double w = c.durationS > 0 ? std::min(1.0, (t - c.atS) / c.durationS) : 1.0;
        level = from + w * (c.to - from);
    }
    return level;
}

} // namespace

std::optional<double> mismatchedGainRatio(double modelGainPctPerK, double plantGainPctPerK) {
    if (!std::isfinite(modelGainPctPerK) || !std::isfinite(plantGainPctPerK) || plantGainPctPerK == 0) {
        return std::nullopt;
    }
    const double ratio = modelGainPctPerK / plantGainPctPerK;
    if (ratio >= 0.5 && ratio <= 2.0) {
        return std::nullopt;
    }
    return ratio;
}

std::string gainMismatchEffect(double ratio) {
    if (ratio < 0) {
        return "its sign is the other, so it steers the hot air the wrong way";
    }
    return ratio < 1 ? "it underrates the hot air's effect, so it over-acts (the setpoint swings towards its "
                       "limits)"
                     : "it overrates the hot air's effect, so it acts too little";
}

namespace {

/// The plant's steady gain: two runs at fixed setpoints 2 K apart, without noise or
/// fluctuation, compared after the line has settled.
double plantGain(const Scenario& scenario, const plant::PlantOptions& plantOptions, double setpointK) {
    Scenario calm = scenario;
    calm.fluctuation = 0;
    calm.unmeasuredDrift = false;
    calm.lengthS = 10;
    plant::PlantOptions o = plantOptions;
    o.noiseScale = 0;
    o.sensors = plant::SensorMode::Ideal; // a step test reads the true product, whatever the plant
    o.unmeasuredDrift = false;
    o.samples = calm.warmupS + calm.lengthS + 1;
    double x[2] = {0, 0};
    for (int i = 0; i < 2; ++i) {
        std::mt19937_64 rng(scenario.seed);
        plant::PlantRandom random(scenario.seed + 1);
        const double sp = setpointK + 2.0 * i;
        plant::PlantLine line(o, scenarioDisturbances(calm, rng), sp, random);
        for (std::size_t k = 0; k < line.size(); ++k) {
            x[i] = line.measure().xOutTruePct;
            line.apply(sp);
        }
    }
    return (x[1] - x[0]) / 2.0;
}

/// Forecasts of a model along a recorded run with the hot air that was applied, scored like
/// the MPC would use them.
ForecastCheck checkForecasts(OutletForecaster& model, const data::SiBatch& record, std::size_t from,
                             int horizon, int stride) {
    ForecastCheck c;
    c.maePct.assign(c.horizonsS.size(), 0.0);
    std::vector<int> counts(c.horizonsS.size(), 0);
    const std::size_t n = record.rows();
    for (std::size_t k = std::max<std::size_t>(from, 1); k + static_cast<std::size_t>(horizon) < n;
         k += static_cast<std::size_t>(stride)) {
        std::vector<double> plan(record.tHotK.begin() + static_cast<long>(k),
                                 record.tHotK.begin() + static_cast<long>(k) + horizon + 1);
        // The decision at row k knows outputs up to k and inputs before k.
        data::SiBatch known = record;
        for (auto* v : {&known.timeS, &known.tHotSpK, &known.tHotK, &known.airSpeedMPerS, &known.feedKgPerS,
                        &known.xInDb, &known.tInK, &known.tAmbK, &known.rhAmb}) {
            v->resize(k);
        }
        for (auto* v : {&known.xOutDb, &known.tOutK, &known.xHdtDb, &known.tHdtK}) {
            v->resize(k + 1);
        }
        const auto f = model.forecast(DecisionPoint{&known, k}, {plan}, horizon);
        if (!f || (*f)[0].size() != static_cast<std::size_t>(horizon) + 1 || !std::isfinite((*f)[0][0])) {
            continue;
        }
        const auto& x = (*f)[0];
        const double d = units::dryToWetPct(record.xOutDb[k]) - x[0];
        for (std::size_t i = 0; i < c.horizonsS.size(); ++i) {
            const auto h = static_cast<std::size_t>(c.horizonsS[i]);
            if (h < x.size() && std::isfinite(x[h])) {
                c.maePct[i] += std::abs(x[h] + d - units::dryToWetPct(record.xOutDb[k + h]));
                ++counts[i];
            }
        }
        ++c.origins;
    }
    for (std::size_t i = 0; i < c.maePct.size(); ++i) {
        c.maePct[i] = counts[i] > 0 ? c.maePct[i] / counts[i] : std::nan("");
    }
    return c;
}

} // namespace

plant::PlantDisturbances scenarioDisturbances(const Scenario& s, std::mt19937_64& rng) {
    const auto n = static_cast<std::size_t>(s.warmupS + s.lengthS + 1);
    plant::PlantDisturbances d;
    for (auto* v : {&d.feedKgPerS, &d.xInDb, &d.tInK, &d.tAmbK, &d.rhAmb, &d.airSpeedMPerS}) {
        v->resize(n);
    }
    d.kDrift.assign(n, 1.0);
    std::normal_distribution<double> unit(0, 1);
    // Ornstein-Uhlenbeck fluctuations as in the plant's own batches, scaled by the scenario.
    struct Ou {
        double a, s, x = 0;
        double next(std::mt19937_64& g, std::normal_distribution<double>& u) { return x = a * x + s * u(g); }
    };
    const auto ou = [&](double tau, double sigma) {
        const double a = std::exp(-1.0 / tau);
        return Ou{a, s.fluctuation * sigma * std::sqrt(1 - a * a)};
    };
    Ou feed = ou(120, 25), xIn = ou(900, 0.0045), tIn = ou(600, 0.8), tAmb = ou(1800, 0.6),
       rh = ou(1200, 0.03), air = ou(60, 0.1);
    Ou drift{std::exp(-1.0 / 2400), 0.05 * std::sqrt(1 - std::exp(-2.0 / 2400))};
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) - s.warmupS;
        d.feedKgPerS[k] =
            units::kgPerHourToKgPerS(levelAt(s, ScenarioInput::Feed, s.feedKgH, t) + feed.next(rng, unit));
        const double xWb = std::clamp(
            levelAt(s, ScenarioInput::InletMoisture, s.xInPct, t) / 100 + xIn.next(rng, unit), 0.12, 0.32);
        d.xInDb[k] = xWb / (1 - xWb);
        d.tInK[k] = units::kKelvinOffset + s.tInC + tIn.next(rng, unit);
        d.tAmbK[k] =
            units::kKelvinOffset + levelAt(s, ScenarioInput::Ambient, s.tAmbC, t) + tAmb.next(rng, unit);
        d.rhAmb[k] = std::clamp(levelAt(s, ScenarioInput::Humidity, s.rhPct, t) / 100 + rh.next(rng, unit),
                                0.05, 0.95);
        d.airSpeedMPerS[k] = s.airSpeedMPerS + air.next(rng, unit);
        if (s.unmeasuredDrift) {
            d.kDrift[k] = 1.0 + drift.next(rng, unit);
        }
    }
    return d;
}

std::unique_ptr<OutletForecaster> forecasterFor(ControllerKind kind, const hybrid::HybridModel& m,
                                                std::string& missing, bool controlThroughPhysics,
                                                bool holdCorrection, bool residualAlongHeldHotAir) {
    switch (kind) {
    case ControllerKind::Pbm:
        return pbmForecaster(m.parameters, m.simulationOptions());
    case ControllerKind::PgrlCc:
        if (!m.pgrlCc) {
            missing = "the model file holds no PGRL-CC residual model (run train)";
            return nullptr;
        }
        return residualForecaster(m.parameters, m.simulationOptions(), m.pgrlCc, controlThroughPhysics,
                                  holdCorrection, residualAlongHeldHotAir);
    case ControllerKind::ExtInputResidual:
        if (!m.extInput) {
            missing = "the model file holds no external-input residual model (run train)";
            return nullptr;
        }
        return residualForecaster(m.parameters, m.simulationOptions(), m.extInput, controlThroughPhysics,
                                  holdCorrection, residualAlongHeldHotAir);
    case ControllerKind::Lstm:
        if (!m.lstm) {
            missing = "the model file holds no LSTM (run train; needs libtorch)";
            return nullptr;
        }
        return lstmForecaster(m.lstm);
    case ControllerKind::Pi:
        break;
    }
    return nullptr;
}

namespace {

/// Appends a reading to a controller's series; a dropout (NaN) holds the last good value, as a DCS
/// shows a value of bad quality, so that no controller is fed a missing cell. A series that never
/// had a good value takes @p fallback.
void appendHeld(std::vector<double>& series, double reading, double fallback) {
    if (std::isfinite(reading)) {
        series.push_back(reading);
    } else {
        series.push_back(series.empty() ? fallback : series.back());
    }
}

/// The record of the run so far as the controller's batch (SI, dry basis).
void appendMeasuredOutputs(data::SiBatch& b, const plant::PlantSample& s) {
    appendHeld(b.xOutDb, units::wetPctToDry(s.xOutPct), units::wetPctToDry(s.xOutTruePct));
    appendHeld(b.tOutK, s.tOutK, s.tOutTrueK);
    // Before the tube-outlet gauges' first good reading, the outlet's stands in (one sample at most).
    appendHeld(b.xHdtDb, units::wetPctToDry(s.xHdtPct), b.xOutDb.back());
    appendHeld(b.tHdtK, s.tHdtK, b.tOutK.back());
    b.keep.push_back(1);
}

void appendAppliedInputs(data::SiBatch& b, const plant::PlantBatch& rec, std::size_t k) {
    b.timeS.push_back(static_cast<double>(k));
    b.tHotSpK.push_back(rec.tHotSpK[k]);
    appendHeld(b.tHotK, rec.tHotK[k], rec.tHotSpK[k]);
    appendHeld(b.airSpeedMPerS, rec.airSpeedMPerS[k], 16.0);
    appendHeld(b.feedKgPerS, rec.feedKgPerS[k], units::kgPerHourToKgPerS(6200));
    appendHeld(b.xInDb, rec.xInDb[k], units::wetPctToDry(22));
    appendHeld(b.tInK, rec.tInK[k], units::celsiusToKelvin(25));
    appendHeld(b.tAmbK, rec.tAmbK[k], units::celsiusToKelvin(22));
    appendHeld(b.rhAmb, rec.rhAmb[k], 0.5);
}

} // namespace

ControlledLine::ControlledLine(const Scenario& scenario, const plant::PlantOptions& plantOptions,
                               plant::PlantRandom& random)
    : m_lastSetpointK(initialSetpointK(scenario)), m_warmupS(static_cast<std::size_t>(scenario.warmupS)),
      m_bandPct(scenario.bandPct), m_controlIntervalS(scenario.controlIntervalS),
      m_warmupTargetPct(scenario.setpointPct) {
    std::mt19937_64 disturbanceRng(scenario.seed);
    m_line = std::make_unique<plant::PlantLine>(plantOptions, scenarioDisturbances(scenario, disturbanceRng),
                                                m_lastSetpointK, random);
    m_record.id = scenario.name;
    m_record.hasXHdt = m_record.hasTHdt = true;
}

ControlledLine ControlledLine::clone(plant::PlantRandom& random) const {
    ControlledLine c;
    c.m_line = std::make_unique<plant::PlantLine>(m_line->clone(random));
    c.m_pi = m_pi;
    c.m_record = m_record;
    c.m_lastSetpointK = m_lastSetpointK;
    c.m_warmupS = m_warmupS;
    c.m_bandPct = m_bandPct;
    c.m_controlIntervalS = m_controlIntervalS;
    c.m_warmupTargetPct = m_warmupTargetPct;
    return c;
}

ControlledLine::Second ControlledLine::step(MpcController* mpc, double targetPct) {
    const std::size_t k = m_line->sample();
    Second out;
    out.sample = m_line->measure();
    appendMeasuredOutputs(m_record, out.sample);
    const plant::PlantSample& s = out.sample;
    const double target = k < m_warmupS ? m_warmupTargetPct : targetPct;
    double sp = m_lastSetpointK;
    if (!mpc || k < m_warmupS) {
        sp = m_pi.next(s.xOutPct, s.xInForControlPct, target);
    } else {
        if ((k - m_warmupS) % static_cast<std::size_t>(m_controlIntervalS) == 0) {
            out.decision = mpc->decide(DecisionPoint{&m_record, k}, m_lastSetpointK, target, m_bandPct,
                                       m_controlIntervalS);
            sp = out.decision->setpointK;
        }
        m_pi.track(sp, s.xOutPct, s.xInForControlPct, target);
    }
    out.setpointK = sp;
    out.hotAirK = m_line->hotAirK();
    m_line->apply(sp);
    appendAppliedInputs(m_record, m_line->record(), k);
    m_lastSetpointK = sp;
    return out;
}

double initialSetpointK(const Scenario& s) {
    return units::kKelvinOffset + 170 + 8.0 * (s.xInPct - 22.0);
}

const char* controllerName(ControllerKind k) {
    switch (k) {
    case ControllerKind::Pbm:
        return "pbm";
    case ControllerKind::ExtInputResidual:
        return "ext_input_residual";
    case ControllerKind::Lstm:
        return "lstm";
    case ControllerKind::PgrlCc:
        return "pgrl_cc";
    case ControllerKind::Pi:
        return "pi";
    }
    return "pi";
}

std::optional<ControllerKind> controllerByName(const std::string& name) {
    for (auto k : {ControllerKind::Pbm, ControllerKind::ExtInputResidual, ControllerKind::Lstm,
                   ControllerKind::PgrlCc, ControllerKind::Pi}) {
        if (name == controllerName(k)) {
            return k;
        }
    }
    return std::nullopt;
}

ClosedLoopMetrics trajectoryMetrics(const std::vector<double>& x, const std::vector<double>& sp,
                                    const std::vector<double>& u, double band, double uBefore) {
    ClosedLoopMetrics m;
    const std::size_t n = std::min({x.size(), sp.size(), u.size()});
    std::size_t outside = 0;
    double prev = uBefore;
    for (std::size_t k = 0; k < n; ++k) {
        const double e = x[k] - sp[k];
        m.iaePctS += std::abs(e); // samples are 1 s apart
        if (std::abs(e) > band) {
            ++outside;
        }
        m.effortK2 += (u[k] - prev) * (u[k] - prev);
        prev = u[k];
    }
    m.violationPct = n > 0 ? 100.0 * static_cast<double>(outside) / static_cast<double>(n) : 0.0;
    return m;
}

plant::PlantOptions scenarioPlantOptions(const Scenario& s) {
    plant::PlantOptions o;
    o.seed = s.seed;
    o.batches = 1;
    o.samples = std::max(200, s.warmupS + s.lengthS +
                                  1); // the plant's own lower limit; the line runs as long as the scenario
    o.noiseScale = s.noiseScale;
    o.plant = s.plant;
    o.sensors = s.sensors;
    o.unmeasuredDrift = s.unmeasuredDrift;
    o.targetXOutPct = s.setpointPct;
    for (const auto& m : s.mechanisms) {
        o.effects[m.mechanism] = m.strength;
        if (m.atS > 0) {
            o.effectOnsetS[m.mechanism] = s.warmupS + m.atS;
        }
    }
    return o;
}

Expected<ClosedLoopResult> runScenario(const Scenario& scenario, const hybrid::HybridModel& model,
                                       const ClosedLoopOptions& options, const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (auto st = scenario.validate(); !st) {
        return st.error();
    }
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    const plant::PlantOptions plantOptions = scenarioPlantOptions(scenario);
    if (auto st = plantOptions.validate(); !st) {
        return st.error();
    }
    std::vector<double> snapshotTimes = options.predictionTimesS;
    if (snapshotTimes.empty()) {
        snapshotTimes.push_back(60);
        for (const auto& step : scenario.setpointSteps) {
            snapshotTimes.push_back(step.atS + 60);
        }
    }
    ClosedLoopResult result;
    result.scenario = scenario;
    const auto warm = static_cast<std::size_t>(scenario.warmupS);
    const std::size_t total = warm + static_cast<std::size_t>(scenario.lengthS);
    const double tauAct = model.parameters[properties::Param::tau_act];
    const std::size_t count = options.controllers.size();
    std::sort(snapshotTimes.begin(), snapshotTimes.end());
    // Each controller's MPC, built (and its history checked) before any runs.
    std::vector<std::unique_ptr<MpcController>> mpcs(count);
    std::vector<std::string> skipped(count);
    for (std::size_t c = 0; c < count; ++c) {
        const ControllerKind kind = options.controllers[c];
        if (kind == ControllerKind::Pi) {
            continue;
        }
        auto f = forecasterFor(kind, model, skipped[c], options.mpc.controlThroughPhysics,
                               options.mpc.holdCorrectionOverHorizon, options.mpc.residualAlongHeldHotAir);
        if (!f) {
            continue;
        }
        mpcs[c] = std::make_unique<MpcController>(std::move(f), options.mpc, tauAct);
        if (mpcs[c]->historyNeeded() > warm) {
            return Error{ErrorKind::BadInput, "scenario " + scenario.name,
                         "warmup_s must be at least " + std::to_string(mpcs[c]->historyNeeded()) +
                             " s: the " + controllerName(kind) + " model needs that much history"};
        }
    }
    // The controllers run two at a time (each is one core's work: a PBM run per plan, the
    // residual forecast, Ipopt), the caller's thread and one more. Only the caller's thread
    // calls the progress callback; the other's progress is shared through `stepsDone`.
    std::vector<ControllerRun> runs(count);
    std::vector<std::optional<data::SiBatch>> records(count);
    std::unique_ptr<std::atomic<std::size_t>[]> stepsDone(new std::atomic<std::size_t>[count]);
    for (std::size_t c = 0; c < count; ++c) {
        stepsDone[c] = 0;
    }
    std::atomic<bool> stopRequested{false};
    const auto runController = [&](std::size_t c, bool reportsProgress) {
        const ControllerKind kind = options.controllers[c];
        const auto runStart = std::chrono::steady_clock::now();
        ControllerRun& run = runs[c];
        run.kind = kind;
        MpcController* mpc = mpcs[c].get();
        if (kind != ControllerKind::Pi && !mpc) {
            run.skippedReason = skipped[c];
            return;
        }
        // Every run sees the same disturbances and noise: fresh generators from the same seed.
        plant::PlantRandom random(scenario.seed + 1);
        ControlledLine line(scenario, plantOptions, random);
        std::vector<double> solveMs, modelMs, gains;
        std::size_t nextSnapshot = 0;
        for (std::size_t k = 0; k < total; ++k) {
            const double t = static_cast<double>(k) - static_cast<double>(warm);
            const double target = scenario.setpointAt(t);
            const ControlledLine::Second second = line.step(mpc, target);
            if (const auto& d = second.decision) {
                ++run.metrics.decisions;
                solveMs.push_back(1e3 * d->solveSeconds);
                modelMs.push_back(1e3 * d->modelSeconds);
                if (!d->fallback) {
                    gains.push_back(d->gainPctPerK);
                }
                if (d->fallback) {
                    ++run.metrics.fallbacks;
                    run.metrics.lastFallbackReason = d->fallbackReason;
                }
                if (nextSnapshot < snapshotTimes.size() && t >= snapshotTimes[nextSnapshot] &&
                    !d->predictedXPct.empty()) {
                    run.predictions.push_back({t, d->predictedXPct});
                    while (nextSnapshot < snapshotTimes.size() && t >= snapshotTimes[nextSnapshot]) {
                        ++nextSnapshot;
                    }
                }
            }
            if (k >= warm) {
                run.timeS.push_back(t);
                run.xOutMeasuredPct.push_back(second.sample.xOutPct);
                run.xOutTruePct.push_back(second.sample.xOutTruePct);
                run.setpointPct.push_back(target);
                run.hotAirSetpointC.push_back(units::kelvinToCelsius(second.setpointK));
                run.hotAirC.push_back(units::kelvinToCelsius(second.hotAirK));
            }
            if (k % 50 == 0) {
                stepsDone[c] = k;
                if (reportsProgress) {
                    std::size_t all = 0;
                    for (std::size_t j = 0; j < count; ++j) {
                        all += stepsDone[j];
                    }
                    if (reportProgress(progress, "mpc",
                                       static_cast<double>(all) / static_cast<double>(total * count),
                                       std::string(controllerName(kind)) + ", step " + std::to_string(k) +
                                           "/" + std::to_string(total))) {
                        stopRequested = true;
                    }
                }
                if (stopRequested) {
                    break;
                }
            }
        }
        stepsDone[c] = total;
        // Metrics over the scored samples.
        // Moves in °C equal moves in K.
        // A run cancelled during its warm-up has no scored part and no setpoint at warm − 1.
        const auto& applied = line.line().record().tHotSpK;
        const double beforeC = warm > 0 && applied.size() >= warm
                                   ? units::kelvinToCelsius(applied[warm - 1])
                                   : units::kelvinToCelsius(initialSetpointK(scenario));
        const ClosedLoopMetrics m = trajectoryMetrics(run.xOutTruePct, run.setpointPct, run.hotAirSetpointC,
                                                      scenario.bandPct, beforeC);
        run.metrics.iaePctS = m.iaePctS;
        run.metrics.effortK2 = m.effortK2;
        run.metrics.violationPct = m.violationPct;
        run.metrics.solveMsMedian = median(solveMs);
        run.metrics.solveMsMax = solveMs.empty() ? 0 : *std::max_element(solveMs.begin(), solveMs.end());
        run.metrics.modelMsMedian = median(modelMs);
        run.metrics.gainPctPerKMedian = median(gains);
        run.ran = true;
        if (kind == ControllerKind::Pi && !stopRequested) {
            records[c] = line.record();
        }
        run.elapsedSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
    };
    // Two controllers at a time (each taking the next in its group; once the caller's thread has
    // none left it relays the other's progress), the LSTM on its own afterwards. Beside another
    // MPC, the LSTM's closed loop depended on what ran next to it: its IAE was 1,696.20 and
    // 1,696.53 %·s on two runs of the same command (the applied setpoints first differ by 3e-4 K,
    // at 234 s, and its loop amplifies that), while alone, beside the PI loop, or one after another
    // it repeated exactly. The physics-based controllers repeat bit for bit two at a time. Which
    // shared state (torch's and the numerics' thread pools, Ipopt's) carries the influence was not
    // pinned down; the report promises that the same command on the same files gives the same
    // numbers.
    std::vector<std::size_t> together, alone;
    for (std::size_t c = 0; c < count; ++c) {
        (options.controllers[c] == ControllerKind::Lstm ? alone : together).push_back(c);
    }
    for (const auto& [group, threads] : {std::pair{&together, 2u}, std::pair{&alone, 1u}}) {
        parallelForFromCaller(
            group->size(), threads,
            [&, group = group](std::size_t i, bool onCallerThread) {
                if (!stopRequested) {
                    runController((*group)[i], onCallerThread);
                }
            },
            [&] {
                std::size_t all = 0;
                for (std::size_t j = 0; j < count; ++j) {
                    all += stepsDone[j];
                }
                if (!stopRequested &&
                    reportProgress(progress, "mpc",
                                   static_cast<double>(all) / static_cast<double>(total * count),
                                   "finishing the last controller")) {
                    stopRequested = true;
                }
            });
    }
    bool stopped = stopRequested;
    std::optional<data::SiBatch> piRecord;
    for (std::size_t c = 0; c < count; ++c) {
        if (records[c]) {
            piRecord = std::move(records[c]);
        }
        // A controller the stop came before never ran: it has no row, as before.
        if (runs[c].ran || !runs[c].skippedReason.empty()) {
            result.runs.push_back(std::move(runs[c]));
        }
    }
    result.plantGainPctPerK = plantGain(scenario, plantOptions, initialSetpointK(scenario));
    // The model error behind the ranking: each MPC's model forecasting the PI run.
    for (auto& run : result.runs) {
        if (stopped || !piRecord || !run.ran || run.kind == ControllerKind::Pi) {
            continue;
        }
        std::string missing;
        if (auto f =
                forecasterFor(run.kind, model, missing, options.mpc.controlThroughPhysics,
                              options.mpc.holdCorrectionOverHorizon, options.mpc.residualAlongHeldHotAir)) {
            run.forecastCheck = checkForecasts(*f, *piRecord, warm, options.mpc.horizonS, 20);
        }
        if (reportProgress(progress, "mpc", 1.0, std::string("forecast check ") + controllerName(run.kind))) {
            stopped = true;
        }
    }
    result.ending.elapsedSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stopped) {
        result.ending.termination = Termination::StoppedKeptBest;
        result.ending.message = "stopped by the user; the runs so far are kept, the last one is partial";
    } else {
        result.ending.message = "scenario " + scenario.name + ": " + std::to_string(result.runs.size()) +
                                " controllers, " + std::to_string(scenario.lengthS) + " scored steps";
    }
    return result;
}

} // namespace drytwin::control
