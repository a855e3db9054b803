// Uses the installed front door (hecal/hecal.h) and libraries: a rotation round trip, a
// pose-table round trip and a calibration of exact pose lists (X and Z recovered).
#include <cmath>
#include <cstdio>
#include <vector>

#include "hecal/hecal.h"

int main() {
  using namespace hecal;
  const Eigen::Vector3d omega(0.1, -0.2, 0.3);
  const double so3_error = (so3::Log(so3::Exp(omega)) - omega).norm();

  io::PoseTable table;
  table.rows.push_back({MakePose(so3::Exp(omega), Eigen::Vector3d(1, 2, 3))});
  const std::string text = io::FormatPoseTable(table, io::PoseWriteOptions{});
  const io::PoseTable back = io::ParsePoseTable(text, "memory", {});
  const double io_error = (back.rows.at(0).pose.matrix() - table.rows[0].pose.matrix()).norm();

  // Eye-in-hand stations with T_base_gripper_i · X · T_camera_target_i = Z exactly.
  const Pose X = MakePose(so3::Exp(Eigen::Vector3d(0.2, 0.1, -0.3)), Eigen::Vector3d(0.05, 0, 0.1));
  const Pose Z = MakePose(so3::Exp(Eigen::Vector3d(-1.0, 0.5, 2.0)), Eigen::Vector3d(0.8, 0.1, 0));
  std::vector<Pose> robot, camera;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d axis(std::cos(i), std::sin(1.7 * i), std::cos(2.3 * i + 1.0));
    const Pose A = MakePose(so3::Exp(0.6 * axis.normalized()), Eigen::Vector3d(0.1 * i, 0.3, 0.5));
    robot.push_back(A);
    camera.push_back((A * X).inverse() * Z);
  }
  jobs::PoseCalibrationOptions options;
  options.setup = handeye::Setup::kEyeInHand;
  const report::ResultDocument document = jobs::CalibratePoses(robot, camera, options).document;
  const double x_error = (document.results.at(0).X.matrix() - X.matrix()).norm();

  std::printf("so3 %.3g io %.3g X %.3g\n", so3_error, io_error, x_error);
  return so3_error < 1e-12 && io_error < 1e-12 && x_error < 1e-6 ? 0 : 1;
}
