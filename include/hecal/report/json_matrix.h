// Eigen matrices and vectors as JSON arrays (rows of numbers), the layout of every hecal result
// file (docs/result-file.md): a matrix is an array of rows, a vector a flat array. Numbers are
// written as nlohmann::json writes doubles (shortest round-trip form); pixel lists, [[u, v], ...],
// rounded to a number of decimals (the per-point fields, result_file.h's kPointDecimals).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

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

inline nlohmann::json JsonPixels(const std::vector<Eigen::Vector2d>& pixels, int decimals) {
  const double scale = std::pow(10.0, decimals);
  nlohmann::json out = nlohmann::json::array();
  for (const Eigen::Vector2d& p : pixels)
    out.push_back({std::round(p.x() * scale) / scale + 0.0,  // + 0.0: no "-0.0"
                   std::round(p.y() * scale) / scale + 0.0});
  return out;
}

}  // namespace hecal::report
