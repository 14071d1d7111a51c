#include "control/Mpc.h"

#include "common/Units.h"
#include "physics/LineInputs.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace drytwin::control {

namespace {
constexpr double kInfinity = 1e19; // Ipopt's "no bound"
}

Status MpcSettings::validate() const {
    if (horizonS < 10 || horizonS > 1200 || blockStartsS.empty() || blockStartsS.front() != 0 ||
        outputStrideS < 1 || outputStrideS > horizonS) {
        return Error{
            ErrorKind::Usage, "MPC settings",
            "need a horizon in [10, 1200] s, blocks starting at 0 and an output stride within the horizon"};
    }
    for (std::size_t j = 1; j < blockStartsS.size(); ++j) {
        if (blockStartsS[j] <= blockStartsS[j - 1] || blockStartsS[j] >= horizonS) {
            return Error{ErrorKind::Usage, "MPC settings",
                         "block starts must increase and lie within the horizon"};
        }
    }
    if (!(trackingWeight > 0) || !(moveWeight >= 0) || !(violationLinear >= 0) || !(violationQuadratic > 0) ||
        !(setpointLowC < setpointHighC) || !(rateLimitKPerS > 0) || !(perturbationK > 0) ||
        maxIterations < 1) {
        return Error{ErrorKind::Usage, "MPC settings",
                     "weights must be positive and the setpoint bounds ordered"};
    }
    return {};
}

MpcController::MpcController(std::unique_ptr<OutletForecaster> model, MpcSettings settings,
                             double actuatorTauS)
    : m_model(std::move(model)), m_settings(std::move(settings)), m_actuatorTauS(actuatorTauS),
      m_solver(m_settings.maxIterations) {}

MpcDecision MpcController::decide(const DecisionPoint& at, double lastSetpointK, double targetPct,
                                  double bandPct, int controlIntervalS) {
    const auto& s = m_settings;
    const auto t0 = std::chrono::steady_clock::now();
    const int n = s.horizonS;
    const auto rows = static_cast<std::size_t>(n) + 1;
    const double lo = units::kKelvinOffset + s.setpointLowC;
    const double hi = units::kKelvinOffset + s.setpointHighC;
    MpcDecision out;

    // Nominal plan: the previous plan shifted to now (successive linearisation), else a hold.
    std::vector<double> nominal(rows, std::clamp(lastSetpointK, lo, hi));
    if (!m_plan.empty() && at.now >= m_planOrigin) {
        const std::size_t shift = at.now - m_planOrigin;
        for (std::size_t m = 0; m < rows; ++m) {
            nominal[m] = m_plan[std::min(m + shift, m_plan.size() - 1)];
        }
    }
    const auto hold = [&](const std::string& why) {
        out.fallback = true;
        out.fallbackReason = why;
        // The plan held may step at a later block's start by that block's whole move (the rate
        // limit times its span); applied now it must still keep the rate limit from the setpoint
        // in force (an LSTM that saw no effect of the hot air jumped 15 K in one second).
        const double step = s.rateLimitKPerS * std::max(1, controlIntervalS);
        out.setpointK =
            std::clamp(std::clamp(nominal[0], lastSetpointK - step, lastSetpointK + step), lo, hi);
        nominal[0] = out.setpointK;
        out.planK = nominal;
        m_plan = nominal;
        m_planOrigin = at.now;
        out.modelSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return out;
    };
    const data::SiBatch& r = *at.record;
    if (at.now < 1 || at.now >= r.xOutDb.size() || !std::isfinite(r.xOutDb[at.now])) {
        return hold("no measurement of the outlet moisture at this step");
    }
    // The hot air at row now follows from the last measured value and the setpoint held since.
    const double a = std::exp(-1.0 / m_actuatorTauS);
    const double hotNow = a * r.tHotK[at.now - 1] + (1 - a) * lastSetpointK;
    std::vector<double> time(rows);
    for (std::size_t m = 0; m < rows; ++m) {
        time[m] = static_cast<double>(m);
    }
    std::vector<double> stepped = nominal;
    for (auto& v : stepped) {
        v += s.perturbationK;
    }
    const auto forecasts =
        m_model->forecast(at,
                          {physics::firstOrderResponse(time, nominal, m_actuatorTauS, hotNow),
                           physics::firstOrderResponse(time, stepped, m_actuatorTauS, hotNow)},
                          n);
    if (!forecasts) {
        return hold("forecast failed: " + forecasts.error().message());
    }
    const auto& f0 = (*forecasts)[0];
    const auto& f1 = (*forecasts)[1];
    if (f0.size() != rows || f1.size() != rows) {
        return hold("forecast too short");
    }
    for (std::size_t i = 0; i < rows; ++i) {
        if (!std::isfinite(f0[i]) || !std::isfinite(f1[i])) {
            return hold("forecast not finite (missing history or inputs)");
        }
    }
    // Output-disturbance update, the same for every model.
    const double disturbance = units::dryToWetPct(r.xOutDb[at.now]) - f0[0];
    std::vector<double> response(rows); // step response per K of setpoint, applied at row now
    for (std::size_t i = 0; i < rows; ++i) {
        response[i] = (f1[i] - f0[i]) / s.perturbationK;
    }
    out.gainPctPerK = response.back();
    const auto blocks = static_cast<Eigen::Index>(s.blockStartsS.size());
    double gainMax = 0;
    for (double g : response) {
        gainMax = std::max(gainMax, std::abs(g));
    }
    // Output points: every stride-th row the moves can reach.
    std::vector<std::size_t> points;
    for (std::size_t i = static_cast<std::size_t>(s.outputStrideS); i < rows;
         i += static_cast<std::size_t>(s.outputStrideS)) {
        if (std::abs(response[i]) > 0.02 * gainMax) {
            points.push_back(i);
        }
    }
    if (points.empty() || gainMax <= 0) {
        return hold("the model shows no effect of the hot air on the outlet moisture");
    }
    const auto np = static_cast<Eigen::Index>(points.size());
    Eigen::MatrixXd g(np, blocks); // dynamic matrix: block j's step starts at blockStartsS[j]
    Eigen::VectorXd free(np);      // forecast along the nominal plan, with the disturbance update
    for (Eigen::Index p = 0; p < np; ++p) {
        const std::size_t i = points[static_cast<std::size_t>(p)];
        free(p) = f0[i] + disturbance;
        for (Eigen::Index j = 0; j < blocks; ++j) {
            const auto start = static_cast<std::size_t>(s.blockStartsS[static_cast<std::size_t>(j)]);
            g(p, j) = i >= start ? response[i - start] : 0.0;
        }
    }
    // Nominal increments of the blocked setpoint, relative to the last applied one.
    Eigen::VectorXd nominalMove(blocks), nominalLevel(blocks), moveLimit(blocks);
    for (Eigen::Index j = 0; j < blocks; ++j) {
        const auto start = static_cast<std::size_t>(s.blockStartsS[static_cast<std::size_t>(j)]);
        nominalLevel(j) = nominal[start];
        const double before =
            j == 0 ? lastSetpointK
                   : nominal[static_cast<std::size_t>(s.blockStartsS[static_cast<std::size_t>(j) - 1])];
        nominalMove(j) = nominal[start] - before;
        const double span = j == 0 ? std::max(1, controlIntervalS)
                                   : s.blockStartsS[static_cast<std::size_t>(j)] -
                                         s.blockStartsS[static_cast<std::size_t>(j) - 1];
        moveLimit(j) = s.rateLimitKPerS * span;
    }
    // QP in x = [δ (block deviations), slack per output point].
    const Eigen::Index nx = blocks + np;
    DenseQp qp;
    qp.h = Eigen::MatrixXd::Zero(nx, nx);
    qp.f = Eigen::VectorXd::Zero(nx);
    const Eigen::VectorXd trackErr = free.array() - targetPct;
    qp.h.topLeftCorner(blocks, blocks) = 2 * s.trackingWeight * g.transpose() * g +
                                         2 * s.moveWeight * Eigen::MatrixXd::Identity(blocks, blocks);
    qp.f.head(blocks) = 2 * s.trackingWeight * g.transpose() * trackErr + 2 * s.moveWeight * nominalMove;
    qp.h.bottomRightCorner(np, np) = 2 * s.violationQuadratic * Eigen::MatrixXd::Identity(np, np);
    qp.f.tail(np).setConstant(s.violationLinear);
    qp.xLow = Eigen::VectorXd::Constant(nx, -kInfinity);
    qp.xHigh = Eigen::VectorXd::Constant(nx, kInfinity);
    qp.xLow.tail(np).setZero();
    // Constraints: band (2 per point), setpoint bounds and rate limits (1 each per block).
    const Eigen::Index nc = 2 * np + 2 * blocks;
    qp.a = Eigen::MatrixXd::Zero(nc, nx);
    qp.aLow = Eigen::VectorXd::Constant(nc, -kInfinity);
    qp.aHigh = Eigen::VectorXd::Constant(nc, kInfinity);
    const double bandLow = targetPct - bandPct;
    const double bandHigh = targetPct + bandPct;
    for (Eigen::Index p = 0; p < np; ++p) {
        qp.a.row(2 * p).head(blocks) = g.row(p); // ŷ − s ≤ high
        qp.a(2 * p, blocks + p) = -1;
        qp.aHigh(2 * p) = bandHigh - free(p);
        qp.a.row(2 * p + 1).head(blocks) = g.row(p); // ŷ + s ≥ low
        qp.a(2 * p + 1, blocks + p) = 1;
        qp.aLow(2 * p + 1) = bandLow - free(p);
    }
    for (Eigen::Index j = 0; j < blocks; ++j) {
        const Eigen::Index c = 2 * np + 2 * j;
        qp.a.row(c).head(j + 1).setOnes(); // level of block j: nominal + Σ_{l≤j} δ_l
        qp.aLow(c) = lo - nominalLevel(j);
        qp.aHigh(c) = hi - nominalLevel(j);
        qp.a(c + 1, j) = 1; // move of block j: nominal move + δ_j
        qp.aLow(c + 1) = -moveLimit(j) - nominalMove(j);
        qp.aHigh(c + 1) = moveLimit(j) - nominalMove(j);
    }
    Eigen::VectorXd start = Eigen::VectorXd::Zero(nx);
    for (Eigen::Index p = 0; p < np; ++p) { // slack start: the nominal plan's violation
        start(blocks + p) = std::max({0.0, free(p) - bandHigh, bandLow - free(p)}) + 1e-3;
    }
    const auto t1 = std::chrono::steady_clock::now();
    const QpSolution sol = m_solver.solve(qp, start);
    out.solveSeconds = sol.seconds;
    out.iterations = sol.iterations;
    out.modelSeconds = std::chrono::duration<double>(t1 - t0).count();
    if (!sol.solved) {
        const double model = out.modelSeconds;
        hold("Ipopt: " + sol.status);
        out.modelSeconds = model;
        return out;
    }
    // The plan: nominal plus the block deviations, clipped to the hard bounds.
    std::vector<double> plan = nominal;
    double shiftSum = 0;
    std::size_t jNext = 0;
    for (std::size_t m = 0; m < rows; ++m) {
        while (jNext < static_cast<std::size_t>(blocks) &&
               static_cast<std::size_t>(s.blockStartsS[jNext]) <= m) {
            shiftSum += sol.x(static_cast<Eigen::Index>(jNext));
            ++jNext;
        }
        plan[m] = std::clamp(nominal[m] + shiftSum, lo, hi);
    }
    out.setpointK = plan[0];
    out.planK = plan;
    out.predictedXPct.resize(rows);
    const Eigen::VectorXd delta = sol.x.head(blocks);
    for (std::size_t i = 0; i < rows; ++i) {
        double y = f0[i] + disturbance;
        for (Eigen::Index j = 0; j < blocks; ++j) {
            const auto st = static_cast<std::size_t>(s.blockStartsS[static_cast<std::size_t>(j)]);
            y += i >= st ? response[i - st] * delta(j) : 0.0;
        }
        out.predictedXPct[i] = y;
    }
    m_plan = plan;
    m_planOrigin = at.now;
    return out;
}

} // namespace drytwin::control
