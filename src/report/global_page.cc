// The page data of the target-free result: see global_page.h.
#include "hecal/report/global_page.h"

#include <Eigen/Geometry>
#include <cmath>

#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"
#include "hecal/report/html_report.h"
#include "hecal/report/json_matrix.h"
#include "hecal/report/report_input.h"

namespace hecal::report {
namespace {

using nlohmann::json;

Eigen::Matrix3d Rotation(const json& rows) {
  Eigen::Matrix3d R;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R(r, c) = rows[r][c].get<double>();
  return R;
}

Eigen::Vector3d Translation(const json& v) {
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

// 1σ per axis of a 6×6 covariance of (ω, v): degrees and millimetres.
json Sigma(const json& covariance) {
  json rotation = json::array(), translation = json::array();
  for (int k = 0; k < 3; ++k) {
    rotation.push_back(std::sqrt(std::max(0.0, covariance[k][k].get<double>())) *
                       kDegreesPerRadian);
    translation.push_back(std::sqrt(std::max(0.0, covariance[k + 3][k + 3].get<double>())) *
                          1000.0);
  }
  return {{"rotation_deg", rotation}, {"translation_mm", translation}};
}

}  // namespace

json GlobalPageData(const json& result, const std::string& title) {
  const Eigen::Matrix3d R = Rotation(result["X"]["rotation"]);
  const Eigen::Vector3d t = Translation(result["X"]["translation_m"]);
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() = R;
  T.topRightCorner<3, 1>() = 1000.0 * t;
  const Eigen::Vector3d omega = so3::Log(R);
  const double angle = omega.norm();
  const Eigen::Vector3d axis =
      angle > 0.0 ? Eigen::Vector3d(omega / angle) : Eigen::Vector3d::UnitZ();
  const Eigen::Quaterniond q(R);
  const json& l_inf = result["l_infinity_X"];
  const double l_inf_angle = so3::Log(R.transpose() * Rotation(l_inf["rotation"])).norm();
  const double l_inf_distance = (Translation(l_inf["translation_m"]) - t).norm();
  const json& covariance = result["covariance"];
  const double ray_sigma = covariance["ray_sigma_rad"].get<double>();
  return {{"kind", "global"},
          {"title", title},
          {"result", result},
          {"answer",
           {{"matrix_mm", JsonRows(T)},
            {"angle_deg", angle * kDegreesPerRadian},
            {"axis", JsonVector(axis)},
            {"quaternion_wxyz", {q.w(), q.x(), q.y(), q.z()}},
            {"sigma", Sigma(covariance["X"])},
            {"sigma_independent_pairs", Sigma(covariance["independent_pairs_X"])},
            {"l_infinity_from_X",
             {{"angle_deg", l_inf_angle * kDegreesPerRadian},
              {"distance_mm", l_inf_distance * 1000.0}}}}},
          {"noise",
           {{"ray_sigma_rad", ray_sigma},
            {"robot_rotation_sigma_deg",
             covariance["robot_rotation_sigma_rad"].get<double>() * kDegreesPerRadian},
            {"robot_translation_sigma_mm",
             covariance["robot_translation_sigma_m"].get<double>() * 1000.0},
            {"robot_sigma", covariance["robot_sigma"]}}}};
}

std::string FormatGlobalReport(std::string_view result_json, const std::string& source,
                               const std::string& title) {
  return FormatHtmlPage(GlobalPageData(ParseGlobalResultForReport(result_json, source), title));
}

}  // namespace hecal::report
