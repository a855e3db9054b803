// Calibrates MoveIt Calibration's 50 real eye-to-hand samples (data/moveit-calibration) through
// the library's front door (hecal/hecal.h), without the CLI: import the samples, calibrate the
// pose lists with `ml` (jobs::CalibratePoses: the convention check, outlier rejection,
// covariance), print X with 1σ.
// Usage: example_calibrate_moveit [pose_samples.json]        (docs/architecture.md: the data flow)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "hecal/hecal.h"

int main(int argc, char** argv) {
  using namespace hecal;
  const std::string path =
      argc > 1 ? argv[1] : HECAL_SOURCE_DIR "/data/moveit-calibration/pose_samples.json";
  try {
    const io::ImportedPoses poses = io::ImportFiles(io::ImportFormat::kMoveit, {path}, {});
    std::vector<Pose> T_base_gripper, T_camera_target;
    for (const io::PoseRow& row : poses.robot.rows) T_base_gripper.push_back(row.pose);
    for (const io::PoseRow& row : poses.camera->rows) T_camera_target.push_back(row.pose);
    jobs::PoseCalibrationOptions options;
    options.setup = handeye::Setup::kEyeToHand;
    options.robot_unit = options.camera_unit = io::LengthUnit::kMetre;  // MoveIt's unit
    const report::ResultDocument document =
        jobs::CalibratePoses(T_base_gripper, T_camera_target, options).document;
    const estimation::CalibrationResult& result = document.results.at(0);
    const Eigen::Vector3d t = result.X.translation();
    const Vector6d sd = result.covariance->X().diagonal().cwiseSqrt();
    const std::string method(estimation::Info(result.method).name);  // the method registry
    std::printf("%s: X = T_base_camera, t = (%.4f, %.4f, %.4f) m ± (%.1f, %.1f, %.1f) mm\n",
                method.c_str(), t.x(), t.y(), t.z(), 1e3 * sd(3), 1e3 * sd(4), 1e3 * sd(5));
    const Eigen::Vector3d r = so3::Log(result.X.linear()) * 180.0 / M_PI;
    std::printf("R = Exp((%.2f, %.2f, %.2f) deg) ± (%.3f, %.3f, %.3f) deg; %zu stations used\n",
                r.x(), r.y(), r.z(), sd(0) * 180.0 / M_PI, sd(1) * 180.0 / M_PI,
                sd(2) * 180.0 / M_PI, result.residuals.size());
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "example_calibrate_moveit: %s\n", error.what());
    return 2;
  }
}
