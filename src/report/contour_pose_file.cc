// The JSON of `hecal contour pose`: see contour_pose_file.h.
#include "hecal/report/contour_pose_file.h"

#include <array>
#include <nlohmann/json.hpp>
#include <string_view>

#include "hecal/geometry/angle_units.h"
#include "hecal/report/json_matrix.h"

namespace hecal::report {

std::string ContourPoseJson(const contour::ShapePose& result) {
  const contour::ContourPose& pose = result.pose;
  nlohmann::json json = {
      {"translation", JsonVector(pose.translation)},
      {"rotation_matrix", JsonRows(pose.rotation)},
      {"euler", JsonVector(pose.euler)},
      {"euler_deg", JsonVector(pose.euler * kDegreesPerRadian)},
      {"sequence", contour::RotationSequence(pose.form)},
      {"units", {{"translation", "unit of --z0"}, {"euler", "rad"}, {"euler_deg", "deg"}}},
  };
  if (result.uncertainty) {
    const contour::ContourPoseUncertainty& ut = *result.uncertainty;
    const std::array<std::string_view, 6> names = contour::PoseParameterNames(pose.form);
    nlohmann::json bias = nlohmann::json::object();
    nlohmann::json parameter_names = nlohmann::json::array();
    for (std::size_t j = 0; j < 6; ++j) {
      bias[std::string(names[j])] = ut.biased[j];
      parameter_names.push_back(names[j]);
    }
    json["parameters"] = parameter_names;
    json["ut_mean"] = JsonVector(ut.mean);
    json["covariance"] = JsonRows(ut.covariance);
    json["bias"] = bias;
  }
  return json.dump(2) + "\n";
}

}  // namespace hecal::report
