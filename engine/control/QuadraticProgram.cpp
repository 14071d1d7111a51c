#include "control/QuadraticProgram.h"

#include "common/BlasThreads.h"

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <chrono>
#include <mutex>

namespace drytwin::control {

namespace {

using Ipopt::Index;
using Ipopt::Number;

/// The QP as Ipopt's nonlinear-programme interface; dense, lower triangle of H.
class QpNlp : public Ipopt::TNLP {
public:
    QpNlp(const DenseQp& qp, const Eigen::VectorXd& start, const Eigen::VectorXd* zLow,
          const Eigen::VectorXd* zHigh, const Eigen::VectorXd* lambda)
        : m_qp(qp), m_start(start), m_zLow(zLow), m_zHigh(zHigh), m_lambda(lambda) {}

    bool get_nlp_info(Index& n, Index& m, Index& nnzJac, Index& nnzH, IndexStyleEnum& style) override {
        n = static_cast<Index>(m_qp.f.size());
        m = static_cast<Index>(m_qp.a.rows());
        nnzJac = n * m;
        nnzH = n * (n + 1) / 2;
        style = C_STYLE;
        return true;
    }
    bool get_bounds_info(Index n, Number* xl, Number* xu, Index m, Number* gl, Number* gu) override {
        for (Index i = 0; i < n; ++i) {
            xl[i] = m_qp.xLow(i);
            xu[i] = m_qp.xHigh(i);
        }
        for (Index i = 0; i < m; ++i) {
            gl[i] = m_qp.aLow(i);
            gu[i] = m_qp.aHigh(i);
        }
        return true;
    }
    bool get_starting_point(Index n, bool initX, Number* x, bool initZ, Number* zl, Number* zu, Index m,
                            bool initLambda, Number* lambda) override {
        if (initX) {
            for (Index i = 0; i < n; ++i) {
                x[i] = std::clamp(m_start(i), m_qp.xLow(i), m_qp.xHigh(i));
            }
        }
        if (initZ) {
            if (!m_zLow || !m_zHigh) {
                return false;
            }
            for (Index i = 0; i < n; ++i) {
                zl[i] = (*m_zLow)(i);
                zu[i] = (*m_zHigh)(i);
            }
        }
        if (initLambda) {
            if (!m_lambda) {
                return false;
            }
            for (Index i = 0; i < m; ++i) {
                lambda[i] = (*m_lambda)(i);
            }
        }
        return true;
    }
    bool eval_f(Index n, const Number* x, bool, Number& obj) override {
        const Eigen::Map<const Eigen::VectorXd> v(x, n);
        obj = 0.5 * v.dot(m_qp.h * v) + m_qp.f.dot(v);
        return true;
    }
    bool eval_grad_f(Index n, const Number* x, bool, Number* grad) override {
        const Eigen::Map<const Eigen::VectorXd> v(x, n);
        Eigen::Map<Eigen::VectorXd>(grad, n) = m_qp.h * v + m_qp.f;
        return true;
    }
    bool eval_g(Index n, const Number* x, bool, Index m, Number* g) override {
        const Eigen::Map<const Eigen::VectorXd> v(x, n);
        Eigen::Map<Eigen::VectorXd>(g, m) = m_qp.a * v;
        return true;
    }
    bool eval_jac_g(Index n, const Number*, bool, Index m, Index, Index* rows, Index* cols,
                    Number* values) override {
        Index k = 0;
        for (Index i = 0; i < m; ++i) {
            for (Index j = 0; j < n; ++j, ++k) {
                if (values) {
                    values[k] = m_qp.a(i, j);
                } else {
                    rows[k] = i;
                    cols[k] = j;
                }
            }
        }
        return true;
    }
    bool eval_h(Index n, const Number*, bool, Number objFactor, Index, const Number*, bool, Index,
                Index* rows, Index* cols, Number* values) override {
        Index k = 0;
        for (Index i = 0; i < n; ++i) {
            for (Index j = 0; j <= i; ++j, ++k) {
                if (values) {
                    values[k] = objFactor * m_qp.h(i, j);
                } else {
                    rows[k] = i;
                    cols[k] = j;
                }
            }
        }
        return true;
    }
    void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number* zl, const Number* zu,
                           Index m, const Number*, const Number* lambda, Number obj, const Ipopt::IpoptData*,
                           Ipopt::IpoptCalculatedQuantities*) override {
        x_ = Eigen::Map<const Eigen::VectorXd>(x, n);
        zLow_ = Eigen::Map<const Eigen::VectorXd>(zl, n);
        zHigh_ = Eigen::Map<const Eigen::VectorXd>(zu, n);
        lambda_ = Eigen::Map<const Eigen::VectorXd>(lambda, m);
        objective_ = obj;
    }

    Eigen::VectorXd x_, zLow_, zHigh_, lambda_;
    double objective_ = 0;

private:
    const DenseQp& m_qp;
    const Eigen::VectorXd& m_start;
    const Eigen::VectorXd* m_zLow;
    const Eigen::VectorXd* m_zHigh;
    const Eigen::VectorXd* m_lambda;
};

std::string statusText(Ipopt::ApplicationReturnStatus s) {
    switch (s) {
    case Ipopt::Solve_Succeeded:
        return "solved";
    case Ipopt::Solved_To_Acceptable_Level:
        return "solved to acceptable level";
    case Ipopt::Infeasible_Problem_Detected:
        return "infeasible";
    case Ipopt::Maximum_Iterations_Exceeded:
        return "iteration limit";
    case Ipopt::Restoration_Failed:
        return "restoration failed";
    case Ipopt::Maximum_CpuTime_Exceeded:
        return "time limit";
    default:
        return "failed (Ipopt status " + std::to_string(static_cast<int>(s)) + ")";
    }
}

/// Ipopt 3.11 (Debian 12) calls the sequential MUMPS, which keeps global state and is not
/// thread-safe; controllers that run side by side (runScenario) take turns at Ipopt.
std::mutex& ipoptMutex() {
    static std::mutex m;
    return m;
}

} // namespace

struct IpoptQpSolver::Impl {
    ~Impl() {
        std::lock_guard<std::mutex> lock(ipoptMutex());
        app = nullptr;
    }
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app;
    bool haveWarm = false;
    Eigen::VectorXd zLow, zHigh, lambda;
};

IpoptQpSolver::IpoptQpSolver(int maxIterations) : m_impl(std::make_unique<Impl>()) {
    blasInCallingThread(); // MUMPS's BLAS, called beside other threads' (common/BlasThreads.h)
    std::lock_guard<std::mutex> lock(ipoptMutex());
    auto& app = m_impl->app;
    app = IpoptApplicationFactory();
    app->Options()->SetIntegerValue("print_level", 0);
    app->Options()->SetStringValue("sb", "yes");
    app->Options()->SetStringValue("hessian_constant", "yes");
    app->Options()->SetStringValue("jac_c_constant", "yes");
    app->Options()->SetStringValue("jac_d_constant", "yes");
    app->Options()->SetStringValue("mehrotra_algorithm", "yes"); // convex QP: Mehrotra's predictor-corrector
    app->Options()->SetNumericValue("tol", 1e-7);
    app->Options()->SetIntegerValue("max_iter", maxIterations);
    app->Options()->SetNumericValue("max_cpu_time", 2.0);
    app->Initialize();
}

IpoptQpSolver::~IpoptQpSolver() = default;
IpoptQpSolver::IpoptQpSolver(IpoptQpSolver&&) noexcept = default;
IpoptQpSolver& IpoptQpSolver::operator=(IpoptQpSolver&&) noexcept = default;

QpSolution IpoptQpSolver::solve(const DenseQp& qp, const Eigen::VectorXd& start) {
    auto& im = *m_impl;
    std::lock_guard<std::mutex> lock(ipoptMutex());
    const auto t0 = std::chrono::steady_clock::now(); // the solve itself, not the wait for the lock
    // Warm start: the demo scenario's median solve falls from 3.8 to 3.1 ms (docs/mpc.md).
    const bool warm = im.haveWarm && im.zLow.size() == qp.f.size() && im.lambda.size() == qp.a.rows();
    im.app->Options()->SetStringValue("warm_start_init_point", warm ? "yes" : "no");
    Ipopt::SmartPtr<QpNlp> nlp = new QpNlp(qp, start, warm ? &im.zLow : nullptr, warm ? &im.zHigh : nullptr,
                                           warm ? &im.lambda : nullptr);
    const Ipopt::ApplicationReturnStatus status = im.app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(nlp));
    QpSolution out;
    out.status = statusText(status);
    out.solved = status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level;
    if (out.solved && nlp->x_.size() == qp.f.size()) {
        out.x = nlp->x_;
        out.objective = nlp->objective_;
        im.zLow = nlp->zLow_;
        im.zHigh = nlp->zHigh_;
        im.lambda = nlp->lambda_;
        im.haveWarm = true;
    } else {
        out.solved = false;
        im.haveWarm = false;
    }
    if (auto stats = im.app->Statistics(); Ipopt::IsValid(stats)) {
        out.iterations = stats->IterationCount();
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

} // namespace drytwin::control
