// Eigen matrices and vectors as JSON arrays (rows of numbers), the layout of every hecal result
// file (docs/result-file.md): a matrix is an array of rows, a vector a flat array. Numbers are
// written as nlohmann::json writes doubles (shortest round-trip form).
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace hecal::report {

inline nlohmann::json JsonRows(const Eigen::MatrixXd& M) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index c = 0; c < M.cols(); ++c) row.push_back(M(r, c));
    rows.push_back(std::move(row));
  }
  return rows;
}

inline nlohmann::json JsonVector(const Eigen::VectorXd& v) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(v(i));
  return out;
}

}  // namespace hecal::report
