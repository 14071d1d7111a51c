#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

namespace drytwin::control {

/// @brief A small dense convex QP: min ½ xᵀHx + fᵀx subject to xLow ≤ x ≤ xHigh and
/// aLow ≤ A x ≤ aHigh (±1e19 for no bound, Ipopt's convention).
struct DenseQp {
    Eigen::MatrixXd h;
    Eigen::VectorXd f;
    Eigen::VectorXd xLow, xHigh;
    Eigen::MatrixXd a;
    Eigen::VectorXd aLow, aHigh;
};

struct QpSolution {
    Eigen::VectorXd x;
    double objective = 0;
    bool solved = false; ///< Ipopt reported an optimal (or acceptable) point
    std::string status;  ///< Ipopt's return status in words
    int iterations = 0;
    double seconds = 0; ///< wall time of the solve
};

/// @brief Solves a sequence of QPs of the same shape with Ipopt (interior point, MUMPS),
/// warm-started from the previous solution and its multipliers when the shape is unchanged.
/// The Hessian and the constraint Jacobian are declared constant, so Ipopt factors little.
class IpoptQpSolver {
public:
    explicit IpoptQpSolver(int maxIterations = 100);
    ~IpoptQpSolver();
    IpoptQpSolver(IpoptQpSolver&&) noexcept;
    IpoptQpSolver& operator=(IpoptQpSolver&&) noexcept;
    /// @brief Solves @p qp from @p start (clipped into the bounds).
    QpSolution solve(const DenseQp& qp, const Eigen::VectorXd& start);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace drytwin::control
