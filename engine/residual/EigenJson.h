#pragma once

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

namespace drytwin::residual {

/// @brief A matrix as {"rows", "cols", "data" (row-major)} in model files.
nlohmann::json matrixToJson(const Eigen::MatrixXd& m);
/// @brief The inverse of matrixToJson; throws std::runtime_error when the sizes disagree.
Eigen::MatrixXd matrixFromJson(const nlohmann::json& j);
/// @brief A vector as a JSON array and back.
nlohmann::json vectorToJson(const Eigen::VectorXd& v);
Eigen::VectorXd vectorFromJson(const nlohmann::json& j);

} // namespace drytwin::residual
