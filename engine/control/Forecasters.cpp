#include "control/Forecasters.h"

#include "common/Units.h"

#include <cmath>
#include <limits>
#include <optional>

namespace drytwin::control {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Rows before the first row a forecast reads that the PBM needs as input history: the parcel
/// leaving at a row entered the line the total transport delay earlier.
std::size_t pbmLead(const properties::ParameterSet& p) {
    return static_cast<std::size_t>(std::ceil(physics::totalDelay(p))) + 3;
}

} // namespace

void holdCorrectionAfter(std::size_t origin, const physics::SimulationResult& pbm,
                         physics::SimulationResult& corrected) {
    const std::size_t n = std::min(corrected.xOutDb.size(), pbm.xOutDb.size());
    if (origin >= n) {
        return;
    }
    const double heldX =
        units::dryToWetPct(corrected.xOutDb[origin]) - units::dryToWetPct(pbm.xOutDb[origin]);
    const double heldT = corrected.tOutK[origin] - pbm.tOutK[origin];
    if (!std::isfinite(heldX) || !std::isfinite(heldT)) {
        return; // no correction at the decision: nothing to hold
    }
    for (std::size_t k = origin + 1; k < n; ++k) {
        corrected.xOutDb[k] = units::wetPctToDry(units::dryToWetPct(pbm.xOutDb[k]) + heldX);
        corrected.tOutK[k] = pbm.tOutK[k] + heldT;
    }
}

namespace {

class PbmForecaster : public OutletForecaster {
public:
    PbmForecaster(properties::ParameterSet p, physics::SimulationOptions o)
        : m_p(std::move(p)), m_o(std::move(o)) {}

    std::size_t historyNeeded() const override { return pbmLead(m_p); }

    Expected<std::vector<std::vector<double>>>
    forecast(const DecisionPoint& at, const std::vector<std::vector<double>>& plans, int horizon) override {
        const std::size_t lead = pbmLead(m_p);
        const std::size_t from = at.now > lead ? at.now - lead : 0;
        std::vector<std::size_t> rows;
        for (std::size_t r = at.now; r <= at.now + static_cast<std::size_t>(horizon); ++r) {
            rows.push_back(r - from);
        }
        std::vector<std::vector<double>> out;
        for (const auto& plan : plans) {
            const data::SiBatch w = planWindow(at, from, plan, horizon);
            auto sim = physics::simulateLine(physics::toLineInputs(w), m_p, m_o, rows);
            if (!sim) {
                return sim.error();
            }
            std::vector<double> x(rows.size());
            for (std::size_t i = 0; i < rows.size(); ++i) {
                x[i] = units::dryToWetPct(sim->xOutDb[i]);
            }
            out.push_back(std::move(x));
        }
        return out;
    }

private:
    properties::ParameterSet m_p;
    physics::SimulationOptions m_o;
};

class ResidualForecaster : public OutletForecaster {
public:
    ResidualForecaster(properties::ParameterSet p, physics::SimulationOptions o,
                       std::shared_ptr<const residual::ResidualModel> m, bool controlThroughPhysics,
                       bool holdCorrection, bool residualAlongHeldHotAir)
        : m_p(std::move(p)), m_o(std::move(o)), m_model(std::move(m)),
          m_controlThroughPhysics(controlThroughPhysics), m_holdCorrection(holdCorrection),
          m_residualAlongHeldHotAir(residualAlongHeldHotAir) {}

    std::size_t historyNeeded() const override { return pbmLead(m_p) + lags(); }

    Expected<std::vector<std::vector<double>>>
    forecast(const DecisionPoint& at, const std::vector<std::vector<double>>& plans, int horizon) override {
        // The view starts where the residual model's lags (and the PBM-change features) begin,
        // and further back by the input-driven correction's memory where the record has it: a
        // correction formed on a short window would take the line to have stood at the window's
        // first inputs, and its level and change over the horizon would be another model's.
        // The PBM's input history reaches a transport delay further back still.
        if (at.now < 1) {
            return Error{ErrorKind::Numerical, "residual forecast", "needs at least one recorded row"};
        }
        const std::size_t back = lags();
        const std::size_t viewFrom = at.now > back ? at.now - back : 0;
        const std::size_t memory = correctionMemory();
        const std::size_t longFrom = viewFrom > memory ? viewFrom - memory : 0;
        const std::size_t lead = pbmLead(m_p);
        std::vector<data::SiBatch> batches;
        std::vector<physics::SimulationResult> sims;
        std::vector<std::size_t> starts;
        batches.reserve(plans.size());
        sims.reserve(plans.size());
        // The PBM over a plan's window from row `start` (the transport delay's lead before it),
        // with the hot air held at heldK when given; the view's batch is the window from start.
        const auto simulateFrom = [&](std::size_t start, const std::vector<double>& plan,
                                      std::optional<double> heldK,
                                      data::SiBatch& view) -> Expected<physics::SimulationResult> {
            const std::size_t from = start > lead ? start - lead : 0;
            data::SiBatch w = planWindow(at, from, plan, horizon);
            view = planWindow(at, start, plan, horizon);
            if (heldK) {
                for (auto* b : {&w, &view}) {
                    std::fill(b->tHotK.begin(), b->tHotK.end(), *heldK);
                    std::fill(b->tHotSpK.begin(), b->tHotSpK.end(), *heldK);
                }
            }
            std::vector<std::size_t> rows;
            for (std::size_t r = start; r < w.rows() + from; ++r) {
                rows.push_back(r - from);
            }
            return physics::simulateLine(physics::toLineInputs(w), m_p, m_o, rows);
        };
        // The learnt residual is forecast along a plan that holds the hot air at its last measured
        // value from now on (MpcSettings::residualAlongHeldHotAir), not along the previous plan
        // shifted: it was learnt under the plant's PI loop, and its answer to planned moves (the
        // loop's answers to the moisture error, taken for the line's response) fed each decision's
        // moves back into the next one's disturbance forecast. The plans differ by the physics.
        const bool flat = m_controlThroughPhysics && m_residualAlongHeldHotAir;
        std::vector<std::vector<double>> plansUsed = plans;
        if (flat) {
            plansUsed.insert(plansUsed.begin(),
                             std::vector<double>(plans.front().size(), at.record->tHotK[at.now - 1]));
        }
        for (std::size_t c = 0; c < plansUsed.size(); ++c) {
            // Only the plans the residual model forecasts need the long window: under
            // controlThroughPhysics the others contribute their PBM run after `now` alone.
            const std::size_t start = (c == 0 || !m_controlThroughPhysics) ? longFrom : viewFrom;
            data::SiBatch view;
            auto sim = simulateFrom(start, plansUsed[c], std::nullopt, view);
            if (!sim) {
                return sim.error();
            }
            batches.push_back(std::move(view));
            sims.push_back(std::move(*sim));
            starts.push_back(start);
        }
        // The input-driven correction is formed from a run with the hot air held at its last
        // measured value over the whole window: it was learnt on data from a line under its own
        // control loop, and its path from the hot air (directly, or through the PBM's proxies)
        // learnt the loop's answers to the moisture error as if they were the line's response
        // (a gain of −0.02 % wb/K where the plant's is −0.09: docs/mpc.md). Held, the correction
        // carries what the disturbances do; the hot air acts through the physics alone.
        std::vector<physics::SimulationResult> correctedBases;
        std::vector<residual::BatchView> views;
        const std::size_t viewCount = m_controlThroughPhysics ? 1 : plansUsed.size();
        if (const auto* correction = usedCorrection()) {
            correctedBases.reserve(viewCount);
            data::SiBatch heldView;
            auto heldRun = simulateFrom(longFrom, plans.front(), at.record->tHotK[at.now - 1], heldView);
            if (!heldRun) {
                return heldRun.error();
            }
            for (std::size_t c = 0; c < viewCount; ++c) {
                correctedBases.push_back(correction->correctedFrom(sims[c], heldView, *heldRun));
                if (m_holdCorrection) {
                    holdCorrectionAfter(at.now - 1 - starts[c], sims[c], correctedBases.back());
                }
                residual::BatchView v{&batches[c], &correctedBases.back(), {0, batches[c].rows()}};
                v.baseCorrected = true;
                views.push_back(v);
            }
        } else {
            for (std::size_t c = 0; c < viewCount; ++c) {
                views.push_back({&batches[c], &sims[c], {0, batches[c].rows()}});
            }
        }
        const std::size_t origin = at.now - 1 - longFrom;
        const auto p = m_model->forecastFrom(views, origin, horizon + 1);
        std::vector<std::vector<double>> out;
        if (!m_controlThroughPhysics) {
            for (const auto& one : p) {
                out.push_back(one.xOutPct);
            }
        } else {
            // The residual along the first (base) plan, added to every plan's own PBM run: the
            // plans differ by the physics' response only.
            const auto& base = p.front();
            for (std::size_t c = flat ? 1 : 0; c < plansUsed.size(); ++c) {
                std::vector<double> x(base.xOutPct.size(), kNaN);
                for (std::size_t i = 0; i < x.size(); ++i) {
                    const std::size_t row = at.now + i - starts[c]; // row now + i of the record
                    const std::size_t baseRow = at.now + i - longFrom;
                    if (row < sims[c].xOutDb.size() && baseRow < sims.front().xOutDb.size()) {
                        x[i] = base.xOutPct[i] + units::dryToWetPct(sims[c].xOutDb[row]) -
                               units::dryToWetPct(sims.front().xOutDb[baseRow]);
                    }
                }
                out.push_back(std::move(x));
            }
        }
        return out;
    }

private:
    std::size_t lags() const { return static_cast<std::size_t>(m_model->options().residualLags) + 4; }
    const residual::InputDrivenCorrection* usedCorrection() const {
        const auto* correction = m_model->inputDriven();
        return correction && correction->used() ? correction : nullptr;
    }
    std::size_t correctionMemory() const {
        const auto* correction = usedCorrection();
        return correction ? correction->memoryRows() : 0;
    }
    properties::ParameterSet m_p;
    physics::SimulationOptions m_o;
    std::shared_ptr<const residual::ResidualModel> m_model;
    bool m_controlThroughPhysics = true;
    bool m_holdCorrection = true;
    bool m_residualAlongHeldHotAir = true;
};

class LstmForecaster : public OutletForecaster {
public:
    explicit LstmForecaster(std::shared_ptr<const baselines::LstmBaseline> m)
        : m_model(std::move(m)), m_follower(*m_model) {}

    std::size_t historyNeeded() const override { return 2; }

    Expected<std::vector<std::vector<double>>>
    forecast(const DecisionPoint& at, const std::vector<std::vector<double>>& plans, int horizon) override {
        if (at.now < 1) {
            return Error{ErrorKind::Numerical, "LSTM forecast", "needs at least one recorded row"};
        }
        // The network is carried to row now−1, whose inputs and outputs are both recorded.
        m_follower.advanceTo(*at.record, at.now - 1);
        std::vector<data::SiBatch> windows;
        windows.reserve(plans.size());
        for (const auto& plan : plans) {
            windows.push_back(planWindow(at, 0, plan, horizon));
        }
        std::vector<const data::SiBatch*> ptrs;
        for (const auto& w : windows) {
            ptrs.push_back(&w);
        }
        const auto p = m_follower.forecast(ptrs, horizon + 1);
        std::vector<std::vector<double>> out;
        for (const auto& one : p) {
            out.push_back(one.xOutPct);
        }
        return out;
    }

private:
    std::shared_ptr<const baselines::LstmBaseline> m_model;
    baselines::LstmBaseline::Follower m_follower;
};

} // namespace

data::SiBatch planWindow(const DecisionPoint& at, std::size_t from, const std::vector<double>& plan,
                         int horizon) {
    const data::SiBatch& r = *at.record;
    const std::size_t end = at.now + static_cast<std::size_t>(horizon) + 1;
    const std::size_t known = std::min(at.now, r.tHotK.size()); // rows with recorded inputs
    data::SiBatch w;
    w.id = r.id;
    w.hasXHdt = r.hasXHdt;
    w.hasTHdt = r.hasTHdt;
    const std::size_t n = end - from;
    for (auto* v : {&w.timeS, &w.tHotSpK, &w.tHotK, &w.airSpeedMPerS, &w.feedKgPerS, &w.xInDb, &w.tInK,
                    &w.tAmbK, &w.rhAmb, &w.xHdtDb, &w.tHdtK, &w.xOutDb, &w.tOutK}) {
        v->assign(n, kNaN);
    }
    w.keep.assign(n, 1);
    const std::size_t last = known > 0 ? known - 1 : 0;
    for (std::size_t k = from; k < end; ++k) {
        const std::size_t i = k - from;
        const std::size_t src = std::min(k, last); // disturbances held at their last recorded value
        w.timeS[i] = static_cast<double>(k);
        w.airSpeedMPerS[i] = r.airSpeedMPerS[src];
        w.feedKgPerS[i] = r.feedKgPerS[src];
        w.xInDb[i] = r.xInDb[src];
        w.tInK[i] = r.tInK[src];
        w.tAmbK[i] = r.tAmbK[src];
        w.rhAmb[i] = r.rhAmb[src];
        if (k < at.now) {
            w.tHotK[i] = r.tHotK[k];
            w.tHotSpK[i] = r.tHotSpK[k];
        } else {
            const std::size_t j = std::min(k - at.now, plan.size() - 1);
            w.tHotK[i] = w.tHotSpK[i] = plan[j];
        }
        if (k <= at.now && k < r.xOutDb.size()) {
            w.xOutDb[i] = r.xOutDb[k];
            w.tOutK[i] = r.tOutK[k];
            w.xHdtDb[i] = r.xHdtDb[k];
            w.tHdtK[i] = r.tHdtK[k];
        }
    }
    return w;
}

std::unique_ptr<OutletForecaster> pbmForecaster(properties::ParameterSet params,
                                                physics::SimulationOptions options) {
    return std::make_unique<PbmForecaster>(std::move(params), std::move(options));
}

std::unique_ptr<OutletForecaster> residualForecaster(properties::ParameterSet params,
                                                     physics::SimulationOptions options,
                                                     std::shared_ptr<const residual::ResidualModel> model,
                                                     bool controlThroughPhysics, bool holdCorrection,
                                                     bool residualAlongHeldHotAir) {
    return std::make_unique<ResidualForecaster>(std::move(params), std::move(options), std::move(model),
                                                controlThroughPhysics, holdCorrection,
                                                residualAlongHeldHotAir);
}

std::unique_ptr<OutletForecaster> lstmForecaster(std::shared_ptr<const baselines::LstmBaseline> model) {
    return std::make_unique<LstmForecaster>(std::move(model));
}

} // namespace drytwin::control
