#include "residual/PolynomialDictionary.h"

#include <functional>

namespace drytwin::residual {

PolynomialDictionary::PolynomialDictionary(std::vector<std::string> names, int degree)
    : m_names(std::move(names)), m_degree(degree) {
    const int n = static_cast<int>(m_names.size());
    // All monomials with non-decreasing input indices, by total degree.
    std::vector<int> current;
    std::function<void(int, int)> add = [&](int start, int remaining) {
        if (remaining == 0) {
            m_terms.push_back(current);
            return;
        }
        for (int i = start; i < n; ++i) {
            current.push_back(i);
            add(i, remaining - 1);
            current.pop_back();
        }
    };
    for (int d = 0; d <= degree; ++d) {
        add(0, d);
    }
    m_mean = Eigen::VectorXd::Zero(n);
    m_scale = Eigen::VectorXd::Ones(n);
}

void PolynomialDictionary::fitScaling(const Eigen::MatrixXd& z) {
    m_mean = z.colwise().mean().transpose();
    m_scale.resize(z.cols());
    for (Eigen::Index j = 0; j < z.cols(); ++j) {
        const double sd = std::sqrt((z.col(j).array() - m_mean(j)).square().mean());
        m_scale(j) = sd > 1e-12 ? sd : 1.0; // a constant input stays constant, not infinite
    }
}

void PolynomialDictionary::setScaling(Eigen::VectorXd mean, Eigen::VectorXd scale) {
    m_mean = std::move(mean);
    m_scale = std::move(scale);
}

std::vector<std::string> PolynomialDictionary::featureNames() const {
    std::vector<std::string> out;
    for (const auto& t : m_terms) {
        if (t.empty()) {
            out.push_back("1");
            continue;
        }
        std::string s;
        for (std::size_t i = 0; i < t.size();) {
            std::size_t j = i;
            while (j < t.size() && t[j] == t[i]) {
                ++j;
            }
            s += (s.empty() ? "" : "*") + m_names[static_cast<std::size_t>(t[i])];
            if (j - i > 1) {
                s += "^" + std::to_string(j - i);
            }
            i = j;
        }
        out.push_back(s);
    }
    return out;
}

std::vector<int> PolynomialDictionary::constantAndLinear() const {
    std::vector<int> idx;
    for (std::size_t f = 0; f < m_terms.size(); ++f) {
        if (m_terms[f].size() <= 1) {
            idx.push_back(static_cast<int>(f));
        }
    }
    return idx;
}

Eigen::VectorXd PolynomialDictionary::lift(const Eigen::VectorXd& z) const {
    const Eigen::VectorXd s = (z - m_mean).cwiseQuotient(m_scale);
    Eigen::VectorXd out(featureCount());
    for (std::size_t f = 0; f < m_terms.size(); ++f) {
        double v = 1.0;
        for (int i : m_terms[f]) {
            v *= s(i);
        }
        out(static_cast<Eigen::Index>(f)) = v;
    }
    return out;
}

Eigen::MatrixXd PolynomialDictionary::lift(const Eigen::MatrixXd& z) const {
    Eigen::MatrixXd out(z.rows(), featureCount());
    for (Eigen::Index r = 0; r < z.rows(); ++r) {
        out.row(r) = lift(Eigen::VectorXd(z.row(r).transpose())).transpose();
    }
    return out;
}

} // namespace drytwin::residual
