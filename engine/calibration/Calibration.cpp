#include "calibration/Calibration.h"

#include "diagnostics/LongRunVariance.h"

#include "common/NumberText.h"
#include "common/Parallel.h"
#include "common/Units.h"
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <optional>

namespace drytwin::calibration {

using properties::Param;
using properties::ParameterSet;

namespace {

constexpr double kPenaltyLoss = 1e6;

/// Maps a free parameter to [0, 1] within its bounds, logarithmically when the bounds are
/// positive and span a decade or more (h_HDT, k_HDT), so that the search is scale-free.
struct Coordinate {
    Param param;
    double lo = 0;
    double hi = 1;
    bool log = false;
    double toValue(double u) const {
        u = std::clamp(u, 0.0, 1.0);
        return log ? std::exp(std::log(lo) + u * (std::log(hi) - std::log(lo))) : lo + u * (hi - lo);
    }
    double toUnit(double v) const {
        return log ? (std::log(v) - std::log(lo)) / (std::log(hi) - std::log(lo)) : (v - lo) / (hi - lo);
    }
};

struct BatchRows {
    std::size_t batch = 0;
    std::vector<std::size_t> rows;
    physics::LineInputs inputs;
};

/// Residuals of one parameter set, by output (moisture in % wb, temperature in K).
struct Residuals {
    std::vector<double> xOut, tOut, xHdt, tHdt;
    /// Sensitivities of the predictions, per free parameter, same layout.
    std::vector<std::vector<double>> dXOut, dTOut, dXHdt, dTHdt;
};

double meanSquare(const std::vector<double>& r) {
    double s = 0;
    for (double v : r) {
        s += v * v;
    }
    return r.empty() ? 0.0 : s / static_cast<double>(r.size());
}

double meanAbs(const std::vector<double>& r) {
    double s = 0;
    for (double v : r) {
        s += std::abs(v);
    }
    return r.empty() ? std::nan("") : s / static_cast<double>(r.size());
}

class Problem {
public:
    Problem(const std::vector<data::SiBatch>& batches, const CalibrationOptions& o)
        : m_batches(batches), m_o(o) {
        std::vector<data::RowRef> rows = o.rows.empty() ? data::calibrationSubset(batches) : o.rows;
        for (const auto& r : rows) {
            if (m_groups.empty() || m_groups.back().batch != r.batch) {
                m_groups.push_back({r.batch, {}, physics::toLineInputs(batches[r.batch])});
            }
            m_groups.back().rows.push_back(r.row);
        }
        m_rowCount = rows.size();
    }
    std::size_t rowCount() const { return m_rowCount; }

    /// Simulates the rows; false when the simulation failed.
    bool residuals(const ParameterSet& p, bool withSensitivities, Residuals& out, std::string* why = nullptr,
                   ErrorKind* kind = nullptr) const {
        physics::SimulationOptions so = m_o.simulation;
        if (withSensitivities) {
            so.sensitivities = m_o.freeParameters;
        }
        out = Residuals{};
        const std::size_t np = m_o.freeParameters.size();
        out.dXOut.resize(np);
        out.dTOut.resize(np);
        out.dXHdt.resize(np);
        out.dTHdt.resize(np);
        // The batches simulate independently: one per core, assembled in batch order.
        std::vector<std::optional<Expected<physics::SimulationResult>>> sims(m_groups.size());
        parallelFor(m_groups.size(), [&](std::size_t i) {
            sims[i].emplace(physics::simulateLine(m_groups[i].inputs, p, so, m_groups[i].rows));
        });
        for (std::size_t gi = 0; gi < m_groups.size(); ++gi) {
            const auto& g = m_groups[gi];
            const auto& sim = *sims[gi];
            if (!sim) {
                if (why) {
                    *why = sim.error().message();
                }
                if (kind) {
                    *kind = sim.error().kind;
                }
                return false;
            }
            const auto& b = m_batches[g.batch];
            for (std::size_t j = 0; j < g.rows.size(); ++j) {
                const std::size_t k = g.rows[j];
                // d(% wb)/dX_db = 100 / (1 + X)².
                const auto wet = [](double x) { return units::dryToWetPct(x); };
                const auto dWet = [](double x) { return 100.0 / ((1 + x) * (1 + x)); };
                if (std::isfinite(b.xOutDb[k]) && std::isfinite(b.tOutK[k])) {
                    out.xOut.push_back(wet(b.xOutDb[k]) - wet(sim->xOutDb[j]));
                    out.tOut.push_back(b.tOutK[k] - sim->tOutK[j]);
                    for (std::size_t q = 0; q < sim->sensitivities.size(); ++q) {
                        out.dXOut[q].push_back(dWet(sim->xOutDb[j]) * sim->sensitivities[q].dXOut[j]);
                        out.dTOut[q].push_back(sim->sensitivities[q].dTOut[j]);
                    }
                }
                if (b.hasXHdt && std::isfinite(b.xHdtDb[k])) {
                    out.xHdt.push_back(wet(b.xHdtDb[k]) - wet(sim->xHdtDb[j]));
                    for (std::size_t q = 0; q < sim->sensitivities.size(); ++q) {
                        out.dXHdt[q].push_back(dWet(sim->xHdtDb[j]) * sim->sensitivities[q].dXHdt[j]);
                    }
                }
                if (b.hasTHdt && std::isfinite(b.tHdtK[k])) {
                    out.tHdt.push_back(b.tHdtK[k] - sim->tHdtK[j]);
                    for (std::size_t q = 0; q < sim->sensitivities.size(); ++q) {
                        out.dTHdt[q].push_back(sim->sensitivities[q].dTHdt[j]);
                    }
                }
            }
        }
        return !out.xOut.empty();
    }

    double loss(const Residuals& r) const {
        const auto& w = m_o.weights;
        return w.xOut * meanSquare(r.xOut) + w.tOut * meanSquare(r.tOut) + w.xHdt * meanSquare(r.xHdt) +
               w.tHdt * meanSquare(r.tHdt);
    }

private:
    const std::vector<data::SiBatch>& m_batches;
    const CalibrationOptions& m_o;
    std::vector<BatchRows> m_groups;
    std::size_t m_rowCount = 0;
};

/// Fisher information of the free parameters under independent Gaussian noise per output,
/// each output's variance estimated from its residuals at the optimum.
Eigen::MatrixXd fisherInformation(const Residuals& r, std::size_t np) {
    Eigen::MatrixXd f = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(np), static_cast<Eigen::Index>(np));
    auto add = [&](const std::vector<double>& res, const std::vector<std::vector<double>>& d) {
        if (res.size() < np + 2 || d.empty() || d[0].size() != res.size()) {
            return;
        }
        const double var = std::max(meanSquare(res), 1e-12);
        for (std::size_t i = 0; i < res.size(); ++i) {
            for (std::size_t a = 0; a < np; ++a) {
                for (std::size_t b = 0; b < np; ++b) {
                    f(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) += d[a][i] * d[b][i] / var;
                }
            }
        }
    };
    add(r.xOut, r.dXOut);
    add(r.tOut, r.dTOut);
    add(r.xHdt, r.dXHdt);
    add(r.tHdt, r.dTHdt);
    return f;
}

/// The "meat" of the sandwich covariance: the long-run (Newey–West, Bartlett kernel) covariance
/// of the per-row scores s_i = Σ_o (∂ŷ_o/∂θ) r_o,i / σ_o², summed over the output groups
/// (X_out with T_out, which share rows; X_hdt; T_hdt). Cross-covariances between groups are
/// left out (they are measured on different row sets). The bandwidth is where the X_out
/// residual's autocorrelation falls below 0.05 (its own memory), at least the Newey–West rule.
Eigen::MatrixXd hacScoreCovariance(const Residuals& r, std::size_t np, int& bandwidth) {
    const auto npi = static_cast<Eigen::Index>(np);
    Eigen::MatrixXd meat = Eigen::MatrixXd::Zero(npi, npi);
    const int ruleOfThumb =
        static_cast<int>(std::floor(4.0 * std::pow(double(r.xOut.size()) / 100.0, 2.0 / 9.0)));
    bandwidth = std::max(ruleOfThumb, diagnostics::bandwidthFromAutocorrelation(
                                          r.xOut, 0.05, std::max(1, static_cast<int>(r.xOut.size()) / 3)));
    const auto addGroup = [&](const std::vector<const std::vector<double>*>& res,
                              const std::vector<const std::vector<std::vector<double>>*>& d) {
        const std::size_t n = res[0]->size();
        if (n < np + 2) {
            return;
        }
        Eigen::MatrixXd scores = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), npi);
        for (std::size_t o = 0; o < res.size(); ++o) {
            if (res[o]->size() != n || (*d[o]).empty() || (*d[o])[0].size() != n) {
                continue;
            }
            const double var = std::max(meanSquare(*res[o]), 1e-12);
            for (std::size_t i = 0; i < n; ++i) {
                for (std::size_t a = 0; a < np; ++a) {
                    scores(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(a)) +=
                        (*d[o])[a][i] * (*res[o])[i] / var;
                }
            }
        }
        meat += scores.transpose() * scores;
        for (int l = 1; l <= bandwidth && static_cast<std::size_t>(l) < n; ++l) {
            const double w = 1.0 - double(l) / double(bandwidth + 1);
            const auto m = static_cast<Eigen::Index>(n) - l;
            const Eigen::MatrixXd gamma = scores.bottomRows(m).transpose() * scores.topRows(m);
            meat += w * (gamma + gamma.transpose());
        }
    };
    addGroup({&r.xOut, &r.tOut}, {&r.dXOut, &r.dTOut});
    if (!r.xHdt.empty()) {
        addGroup({&r.xHdt}, {&r.dXHdt});
    }
    if (!r.tHdt.empty()) {
        addGroup({&r.tHdt}, {&r.dTHdt});
    }
    return meat;
}

} // namespace

// What the user asked for (the command line's --free, --bound, the window's fields): wrong usage
// (exit 2), not bad data.
Status CalibrationOptions::validate() const {
    if (freeParameters.empty()) {
        return Error{ErrorKind::Usage, "free parameters", "name at least one parameter to calibrate"};
    }
    for (std::size_t i = 0; i < freeParameters.size(); ++i) {
        const auto& info = properties::info(freeParameters[i]);
        if (info.fixed) {
            return Error{ErrorKind::Usage, std::string(info.symbol),
                         "is a physical constant and cannot be freed"};
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (freeParameters[j] == freeParameters[i]) {
                return Error{ErrorKind::Usage, std::string(info.symbol), "is named twice"};
            }
        }
    }
    for (const auto& [p, b] : bounds) {
        const auto& info = properties::info(p);
        if (!(b.first < b.second) || b.first < info.lower || b.second > info.upper ||
            !std::isfinite(b.first) || !std::isfinite(b.second)) {
            return Error{ErrorKind::Usage, std::string(info.symbol),
                         "bounds must satisfy " + shortNumber(info.lower) + " ≤ lower < upper ≤ " +
                             shortNumber(info.upper) + " " + std::string(info.unit)};
        }
    }
    const double ws[] = {weights.xOut, weights.tOut, weights.xHdt, weights.tHdt};
    for (double w : ws) {
        if (!(w >= 0 && std::isfinite(w))) {
            return Error{ErrorKind::Usage, "loss weights", "must be finite and ≥ 0"};
        }
    }
    if (weights.xOut + weights.tOut + weights.xHdt + weights.tHdt <= 0) {
        return Error{ErrorKind::Usage, "loss weights", "at least one must be positive"};
    }
    if (maxEvaluations < 10) {
        return Error{ErrorKind::Usage, "max evaluations", "must be at least 10"};
    }
    return simulation.validate();
}

Expected<CalibrationResult> calibrate(const std::vector<data::SiBatch>& batches, const ParameterSet& start,
                                      const CalibrationOptions& options, const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    if (auto st = start.validate(); !st) {
        return st.error();
    }
    if (batches.empty()) {
        return Error{ErrorKind::BadInput, "calibration data", "no batches"};
    }
    for (const auto& r : options.rows) {
        if (r.batch >= batches.size() || r.row >= batches[r.batch].rows()) {
            return Error{ErrorKind::BadInput, "calibration rows", "a row lies outside the data"};
        }
    }
    Problem problem(batches, options);
    if (problem.rowCount() < options.freeParameters.size() + 2) {
        return Error{ErrorKind::BadInput, "calibration data",
                     "only " + std::to_string(problem.rowCount()) +
                         " usable rows after cleaning; calibration needs more rows than parameters"};
    }
    std::vector<Coordinate> coords;
    for (Param p : options.freeParameters) {
        const auto& info = properties::info(p);
        Coordinate c{p, info.lower, info.upper, false};
        if (const auto it = options.bounds.find(p); it != options.bounds.end()) {
            c.lo = it->second.first;
            c.hi = it->second.second;
        }
        c.log = c.lo > 0 && c.hi / c.lo >= 10;
        coords.push_back(c);
    }
    const std::size_t np = coords.size();

    CalibrationResult result;
    result.rowsUsed = problem.rowCount();
    result.algorithm = "NLopt GN_CRS2_LM then LN_BOBYQA";
    Residuals res;
    std::string why;
    // An input the model cannot take (a cell out of range: bad data, exit 3 as `simulate` gives)
    // is not a numerical failure of the starting parameters (exit 4).
    ErrorKind failure = ErrorKind::Numerical;
    if (!problem.residuals(start, false, res, &why, &failure)) {
        return Error{failure == ErrorKind::BadInput ? ErrorKind::BadInput : ErrorKind::Numerical,
                     "calibration start", "the model fails at the starting parameters: " + why};
    }
    result.before = {problem.loss(res), meanAbs(res.xOut), meanAbs(res.tOut)};

    // The objective, shared by both phases.
    struct State {
        const Problem* problem;
        const std::vector<Coordinate>* coords;
        ParameterSet base;
        CalibrationResult* result;
        const Progress* progress;
        const CalibrationOptions* options;
        std::string phase;
        double best = std::numeric_limits<double>::infinity();
        std::vector<double> bestUnit;
        bool cancelled = false;
        bool stoppedKeepBest = false; ///< the user asked to stop and keep the best point so far
        int budget = 0;
    } state{&problem,  &coords,  start,    &result,
            &progress, &options, "global", std::numeric_limits<double>::infinity(),
            {},        false,    false,    options.maxEvaluations};
    for (const auto& c : coords) {
        state.bestUnit.push_back(std::clamp(c.toUnit(start[c.param]), 0.0, 1.0));
    }
    state.best = result.before.loss;

    const auto objective = [](unsigned n, const double* u, double*, void* data) -> double {
        auto& s = *static_cast<State*>(data);
        if (s.cancelled || s.stoppedKeepBest) {
            // NLopt may evaluate a whole population before it sees the stop request.
            throw nlopt::forced_stop();
        }
        ParameterSet p = s.base;
        IterationRecord rec;
        rec.evaluation = s.result->evaluations + 1;
        rec.phase = s.phase;
        for (unsigned i = 0; i < n; ++i) {
            p[(*s.coords)[i].param] = (*s.coords)[i].toValue(u[i]);
            rec.values.push_back(p[(*s.coords)[i].param]);
        }
        Residuals r;
        double loss = kPenaltyLoss;
        if (s.problem->residuals(p, false, r)) {
            loss = s.problem->loss(r);
        } else {
            rec.failed = true;
            ++s.result->failedEvaluations;
        }
        if (!std::isfinite(loss)) {
            loss = kPenaltyLoss;
        }
        ++s.result->evaluations;
        if (loss < s.best) {
            s.best = loss;
            s.bestUnit.assign(u, u + n);
        }
        rec.loss = loss;
        rec.bestLoss = s.best;
        s.result->history.push_back(rec);
        const auto action = progressAction(
            *s.progress, "calibrate", std::min(1.0, static_cast<double>(s.result->evaluations) / s.budget),
            s.phase + " search, loss " + std::to_string(s.best));
        if (action != ProgressAction::Continue) {
            (action == ProgressAction::StopKeepBest ? s.stoppedKeepBest : s.cancelled) = true;
            throw nlopt::forced_stop();
        }
        return loss;
    };

    const int globalEvals =
        !options.globalSearch
            ? 0
            : std::min(options.maxEvaluations / 2,
                       options.globalEvaluations > 0 ? options.globalEvaluations : 60 * static_cast<int>(np));
    state.budget =
        globalEvals + std::min(options.maxEvaluations - globalEvals, 40 * static_cast<int>(np) + 40);
    nlopt::srand(options.seed); // NLopt's stochastic global methods draw from this seed
    auto run = [&](nlopt::algorithm algorithm, int maxEval, std::vector<double>& x) {
        nlopt::opt opt(algorithm, static_cast<unsigned>(np));
        opt.set_lower_bounds(std::vector<double>(np, 0.0));
        opt.set_upper_bounds(std::vector<double>(np, 1.0));
        opt.set_min_objective(objective, &state);
        opt.set_maxeval(maxEval);
        if (algorithm == nlopt::LN_BOBYQA) {
            opt.set_xtol_rel(options.localRelTol);
            opt.set_initial_step(std::vector<double>(np, 0.02));
        } else {
            opt.set_population(static_cast<unsigned>(10 * (np + 1)));
        }
        double f = 0;
        try {
            opt.optimize(x, f);
        } catch (const nlopt::forced_stop&) {
        } catch (const std::exception&) {
            // NLopt gives up (roundoff, too many failures): keep the best point found so far.
        }
    };
    std::vector<double> x = state.bestUnit;
    if (globalEvals > 0) {
        run(nlopt::GN_CRS2_LM, globalEvals, x);
    }
    if (state.cancelled) {
        return cancelledError("calibrate");
    }
    if (!state.stoppedKeepBest) {
        state.phase = "local";
        x = state.bestUnit;
        run(nlopt::LN_BOBYQA, std::max(1, options.maxEvaluations - result.evaluations), x);
        if (state.cancelled) {
            return cancelledError("calibrate");
        }
    }
    if (state.stoppedKeepBest) {
        result.ending.termination = Termination::StoppedKeptBest;
        result.ending.message = "stopped by the user after " + std::to_string(result.evaluations) +
                                " evaluations (" + state.phase + " search); the best parameters found so far";
    } else if (result.evaluations >= options.maxEvaluations) {
        result.ending.termination = Termination::BudgetExhausted;
        result.ending.message =
            "used the budget of " + std::to_string(options.maxEvaluations) + " evaluations";
    } else {
        result.ending.termination = Termination::Converged;
        result.ending.message = "BOBYQA met its relative parameter tolerance";
    }

    result.parameters = start;
    for (std::size_t i = 0; i < np; ++i) {
        result.parameters[coords[i].param] = coords[i].toValue(state.bestUnit[i]);
    }
    // Fit after, with sensitivities for the Fisher information.
    // The sensitivity run needs more solver steps than a plain one; if it fails, the fit
    // stands and the intervals are reported as unknown (NaN).
    Residuals at;
    const bool withSensitivities = options.intervals && problem.residuals(result.parameters, true, at, &why);
    if (!withSensitivities && !problem.residuals(result.parameters, false, at, &why)) {
        return Error{ErrorKind::Numerical, "calibration result", "the model fails at the optimum: " + why};
    }
    result.after = {problem.loss(at), meanAbs(at.xOut), meanAbs(at.tOut)};
    const Eigen::MatrixXd fisher = withSensitivities ? fisherInformation(at, np)
                                                     : Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(np),
                                                                             static_cast<Eigen::Index>(np));
    Eigen::MatrixXd cov =
        Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(np), static_cast<Eigen::Index>(np),
                                  std::numeric_limits<double>::quiet_NaN());
    Eigen::MatrixXd fisherCov = cov;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(fisher);
    if (lu.isInvertible()) {
        // The residuals are strongly autocorrelated (slow drift, transport delay), so the Fisher
        // covariance F⁻¹, which assumes independent rows, is far too narrow. The sandwich
        // F⁻¹ M F⁻¹ with M the HAC covariance of the scores is consistent either way.
        fisherCov = lu.inverse();
        int bandwidth = 0;
        const Eigen::MatrixXd meat = hacScoreCovariance(at, np, bandwidth);
        cov = fisherCov * meat * fisherCov;
        result.intervalMethod = "sandwich F^-1 M F^-1, M Newey-West (Bartlett) over " +
                                std::to_string(bandwidth) + " lags of the calibration rows";
    }
    for (std::size_t i = 0; i < np; ++i) {
        Estimate e;
        e.param = coords[i].param;
        e.value = result.parameters[e.param];
        const double var = cov(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
        const double varFisher = fisherCov(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
        e.standardErrorFisher = varFisher > 0 ? std::sqrt(varFisher) : std::nan("");
        e.standardError = var > 0 ? std::sqrt(var) : std::nan("");
        // Held within the parameter's range: a value at its bound (the inlet gauge's scatter share
        // at 1) had an interval reaching to 1.12, a share no gauge can have. At a bound the Wald
        // interval is one-sided at best; atBound says so beside it.
        e.ci95Low = std::max(coords[i].lo, e.value - 1.96 * e.standardError);
        e.ci95High = std::min(coords[i].hi, e.value + 1.96 * e.standardError);
        const double u = state.bestUnit[i];
        e.atBound = u < 1e-3 || u > 1 - 1e-3;
        result.estimates.push_back(e);
    }
    reportProgress(progress, "calibrate", 1.0, "done");
    result.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    result.ending.elapsedSeconds = result.elapsedSeconds;
    return result;
}

} // namespace drytwin::calibration
