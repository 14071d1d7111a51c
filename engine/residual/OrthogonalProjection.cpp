#include "residual/OrthogonalProjection.h"

namespace drytwin::residual {

Eigen::MatrixXd projectionCoefficients(const Eigen::MatrixXd& base, const Eigen::MatrixXd& residual,
                                       const Eigen::VectorXd& w) {
    const Eigen::MatrixXd bw = base.array().colwise() * w.array();
    Eigen::MatrixXd gram = base.transpose() * bw;
    gram.diagonal().array() += 1e-10 * gram.diagonal().maxCoeff();
    return gram.ldlt().solve(bw.transpose() * residual);
}

} // namespace drytwin::residual
