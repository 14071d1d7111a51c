#include "diagnostics/Stability.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drytwin::diagnostics {

std::vector<std::complex<double>> eigenvalues(const Eigen::MatrixXd& a) {
    if (a.rows() == 0) {
        return {};
    }
    Eigen::EigenSolver<Eigen::MatrixXd> solver(a, false);
    std::vector<std::complex<double>> ev(solver.eigenvalues().data(),
                                         solver.eigenvalues().data() + solver.eigenvalues().size());
    std::stable_sort(ev.begin(), ev.end(), [](auto x, auto y) { return std::abs(x) > std::abs(y); });
    return ev;
}

double spectralRadius(const Eigen::MatrixXd& a) {
    const auto ev = eigenvalues(a);
    return ev.empty() ? 0.0 : std::abs(ev.front());
}

std::vector<double> contractionRates(const Eigen::MatrixXd& a) {
    std::vector<double> rates;
    for (const auto& l : eigenvalues(a)) {
        const double m = std::abs(l);
        rates.push_back(m > 0 ? -std::log(m) : std::numeric_limits<double>::infinity());
    }
    return rates;
}

double certificateMaxEigenvalue(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p, double alpha) {
    Eigen::MatrixXd m = a.transpose() * p * a - alpha * alpha * p;
    m = 0.5 * (m + m.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(m, Eigen::EigenvaluesOnly);
    return solver.eigenvalues().maxCoeff();
}

} // namespace drytwin::diagnostics
