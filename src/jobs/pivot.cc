// Pivot calibration as one job: see pivot.h.
#include "hecal/jobs/pivot.h"

#include "hecal/core/options_check.h"
#include "hecal/jobs/pose_calibration.h"

namespace hecal::jobs {

bool PivotPoseOptions::IsValid(std::string* why) const {
  if (!pivot.IsValid(why)) return false;
  if (source.empty()) {
    return Invalid(why, "PivotPoseOptions.source", "is empty",
                   "name the robot poses (e.g. T_base_flange)");
  }
  return true;
}

report::PivotDocument CalibratePivotPoses(const std::vector<Pose>& T_base_flange,
                                          const PivotPoseOptions& options) {
  RequireValid(options);
  if (!options.station_ids.empty() && options.station_ids.size() != T_base_flange.size()) {
    throw InputError("PivotPoseOptions.station_ids", 0,
                     "has " + std::to_string(options.station_ids.size()) + " ids for " +
                         std::to_string(T_base_flange.size()) + " poses",
                     "give one id per pose, or none");
  }
  CheckPoseList(T_base_flange, options.source);
  std::vector<Pose> poses = T_base_flange;
  for (Pose& T : poses) T.translation() *= io::MetresPer(options.unit);
  report::PivotDocument document;
  document.result = estimation::CalibratePivot(poses, options.pivot);
  document.unit = options.unit;
  document.outlier_rejection = options.pivot.reject_outliers;
  document.station_ids = options.station_ids;
  for (size_t i = document.station_ids.size(); i < poses.size(); ++i) {
    document.station_ids.push_back(std::to_string(i));
  }
  return document;
}

bool PivotFileOptions::IsValid(std::string* why) const {
  if (!pivot.IsValid(why)) return false;
  if (robot.empty()) {
    return Invalid(why, "PivotFileOptions.robot", "is empty",
                   "give the robot pose table (T_base_flange, one row per orientation)");
  }
  return read.IsValid(why);
}

report::PivotDocument CalibratePivotFile(const PivotFileOptions& options) {
  RequireValid(options);
  const io::PoseTable table = io::ReadPoseTable(options.robot, options.read);
  std::vector<Pose> poses;
  report::PivotDocument document;
  for (size_t i = 0; i < table.rows.size(); ++i) {
    poses.push_back(table.rows[i].pose);
    document.station_ids.push_back(table.rows[i].id.value_or(std::to_string(i)));
  }
  document.result = estimation::CalibratePivot(poses, options.pivot);
  document.unit = table.unit;
  document.outlier_rejection = options.pivot.reject_outliers;
  for (const std::string& warning : table.warnings) document.result.warnings.push_back(warning);
  return document;
}

}  // namespace hecal::jobs
