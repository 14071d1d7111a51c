#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace drytwin::residual {

/// @brief Polynomial lifting Ψ(z) of Eq. (26): [1, z_i, z_i², z_i z_j, …] up to a degree, on
/// standardised inputs ((z − mean) / std, learned from training data).
class PolynomialDictionary {
public:
    PolynomialDictionary() = default;
    /// @brief @p degree 1..3; @p names name the inputs (for feature names in files and plots).
    PolynomialDictionary(std::vector<std::string> names, int degree);

    /// @brief Learns the standardisation from rows of Z (one row per snapshot).
    void fitScaling(const Eigen::MatrixXd& z);
    void setScaling(Eigen::VectorXd mean, Eigen::VectorXd scale);

    int degree() const { return m_degree; }
    int inputCount() const { return static_cast<int>(m_names.size()); }
    int featureCount() const { return static_cast<int>(m_terms.size()); }
    const Eigen::VectorXd& mean() const { return m_mean; }
    const Eigen::VectorXd& scale() const { return m_scale; }
    const std::vector<std::string>& inputNames() const { return m_names; }
    /// @brief "1", "X_HDT", "X_HDT^2", "X_HDT*T_amb", …
    std::vector<std::string> featureNames() const;
    /// @brief Indices of the constant and the linear terms (the default base set of Eq. 27).
    std::vector<int> constantAndLinear() const;

    /// @brief Ψ(z) for one input vector.
    Eigen::VectorXd lift(const Eigen::VectorXd& z) const;
    /// @brief Ψ for every row of Z; rows are snapshots.
    Eigen::MatrixXd lift(const Eigen::MatrixXd& z) const;

private:
    std::vector<std::string> m_names;
    int m_degree = 2;
    std::vector<std::vector<int>> m_terms; ///< input indices multiplied in each feature ({} = 1)
    Eigen::VectorXd m_mean;
    Eigen::VectorXd m_scale;
};

} // namespace drytwin::residual
