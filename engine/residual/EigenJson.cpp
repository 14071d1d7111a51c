// Eigen matrices and vectors in model files (JSON).
#include "residual/EigenJson.h"

#include <stdexcept>
#include <vector>

namespace drytwin::residual {

nlohmann::json matrixToJson(const Eigen::MatrixXd& m) {
    std::vector<double> data;
    data.reserve(static_cast<std::size_t>(m.size()));
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        for (Eigen::Index c = 0; c < m.cols(); ++c) {
            data.push_back(m(r, c));
        }
    }
    return {{"rows", m.rows()}, {"cols", m.cols()}, {"data", data}};
}

Eigen::MatrixXd matrixFromJson(const nlohmann::json& j) {
    const auto rows = j.at("rows").get<Eigen::Index>();
    const auto cols = j.at("cols").get<Eigen::Index>();
    const auto data = j.at("data").get<std::vector<double>>();
    if (rows < 0 || cols < 0 || static_cast<Eigen::Index>(data.size()) != rows * cols) {
        throw std::runtime_error("matrix data size does not match rows × cols");
    }
    Eigen::MatrixXd m(rows, cols);
    for (Eigen::Index r = 0; r < rows; ++r) {
        for (Eigen::Index c = 0; c < cols; ++c) {
            m(r, c) = data[static_cast<std::size_t>(r * cols + c)];
        }
    }
    return m;
}

nlohmann::json vectorToJson(const Eigen::VectorXd& v) {
    return std::vector<double>(v.data(), v.data() + v.size());
}

Eigen::VectorXd vectorFromJson(const nlohmann::json& j) {
    const auto v = j.get<std::vector<double>>();
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

} // namespace drytwin::residual
