// The result file of `hecal pose`: see pose_file.h.
#include "hecal/report/pose_file.h"

#include <nlohmann/json.hpp>

#include "hecal/geometry/rotation.h"
#include "hecal/geometry/so3.h"
#include "hecal/report/json_matrix.h"
#include "hecal/version.h"

namespace hecal::report {

std::string PoseResultJson(const pose::PoseEstimate& estimate,
                           const std::vector<std::optional<std::string>>& point_ids,
                           io::LengthUnit unit) {
  const double scale = 1.0 / io::MetresPer(unit);
  const Pose& T = estimate.T_camera_target;
  Eigen::Matrix4d M = T.matrix();
  M.topRightCorner<3, 1>() *= scale;
  const Eigen::Vector3d t = T.translation() * scale;
  const Eigen::Quaterniond q = QuaternionFromMatrix(T.linear());
  const Eigen::Vector3d rvec = so3::Log(T.linear());
  nlohmann::json result = {
      {"hecal_version", hecal::kVersion},
      {"method", estimate.method},
      {"units", {{"length", io::UnitName(unit)}, {"angle", "rad"}}},
      {"T_camera_target",
       {{"frame", "T_camera_target"},
        {"matrix", JsonRows(M)},
        {"translation", {t.x(), t.y(), t.z()}},
        {"quaternion_wxyz", {q.w(), q.x(), q.y(), q.z()}},
        {"rotation_vector", {rvec.x(), rvec.y(), rvec.z()}}}},
      {"reprojection_rms_px", estimate.rms_px},
  };
  if (estimate.covariance) {
    Vector6d s;
    s << 1.0, 1.0, 1.0, scale, scale, scale;
    const Matrix6d C = s.asDiagonal() * *estimate.covariance * s.asDiagonal();
    result["covariance"] = {{"matrix", JsonRows(0.5 * (C + C.transpose()))},
                            {"parameterization", "right, (rx,ry,rz,tx,ty,tz)"},
                            {"pixel_sigma", estimate.sigma_px},
                            {"pixel_sigma_source", pose::SigmaSourceName(estimate.sigma_source)}};
  }
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t k = 0; k < estimate.residuals_px.size(); ++k) {
    const std::optional<std::string>& id = k < point_ids.size() ? point_ids[k] : std::nullopt;
    const Eigen::Vector2d& e = estimate.residuals_px[k];
    points.push_back({{"id", id ? nlohmann::json(*id) : nlohmann::json(k + 1)},
                      {"residual_px", {e.x(), e.y()}}});
  }
  result["points"] = std::move(points);
  result["warnings"] = estimate.warnings;
  return result.dump(2) + "\n";
}

}  // namespace hecal::report
