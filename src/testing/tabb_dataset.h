// Test support (not installed): the bundled real data set data/tabb-rwhe-dataset1 (Tabb & Ahmad
// Yousef 2017, 88 eye-in-hand stations; see its SOURCE.md) in hecal's conventions, read with a
// small local parser so solver tests do not depend on the io layer.
//   robot_cali.txt  88 blocks of 4×4 T_gripper_base in mm      → inverted: T_base_gripper
//   cali.txt        per line: name, K (9), R (9, row-major), t (3, mm), distortion (5), 3 zeros
//                   = T_camera_target
//   rwhe_AA_RPI/transformations.txt  Tabb's result, model target2cam_i · X_T = Z_T ·
//                   base2gripper_i with X_T = T_target_base and Z_T = T_camera_gripper, so
//                   hecal's X = T_gripper_camera = Z_T⁻¹ and Z = T_base_target = X_T⁻¹.
// Everything is converted to metres. Tabb's rotations (6 significant digits) are projected on
// SO(3).
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/geometry/nearest_rotation.h"
#include "hecal/geometry/types.h"

namespace hecal::testing {

struct TabbDataset {
  std::vector<Pose> T_base_gripper;
  std::vector<Pose> T_camera_target;
  Pose X;  // Tabb's reference, hecal meaning (eye-in-hand)
  Pose Z;
};

inline Pose TabbPose(const Eigen::Matrix3d& R, const Eigen::Vector3d& t_mm) {
  return MakePose(NearestRotationSvd(R), 1e-3 * t_mm);
}

// Reads a 4×4 row-major matrix (the last row is read and ignored).
inline Pose ReadTabbMatrix(std::istream& in) {
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) in >> M(r, c);
  }
  if (!in) throw std::runtime_error("tabb dataset: malformed 4x4 matrix");
  return TabbPose(M.topLeftCorner<3, 3>(), M.topRightCorner<3, 1>());
}

inline TabbDataset LoadTabbDataset() {
  const std::string dir = std::string(HECAL_SOURCE_DIR) + "/data/tabb-rwhe-dataset1/";
  TabbDataset data;
  std::ifstream robot(dir + "robot_cali.txt");
  int count = 0;
  robot >> count;
  for (int i = 0; i < count; ++i) data.T_base_gripper.push_back(ReadTabbMatrix(robot).inverse());

  std::ifstream camera(dir + "cali.txt");
  camera >> count;
  std::string line;
  std::getline(camera, line);
  for (int i = 0; i < count; ++i) {
    std::getline(camera, line);
    std::istringstream fields(line);
    std::string name;
    double value = 0.0;
    fields >> name;
    for (int k = 0; k < 9; ++k) fields >> value;  // intrinsics
    Eigen::Matrix3d R;
    Eigen::Vector3d t;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) fields >> R(r, c);
    }
    fields >> t.x() >> t.y() >> t.z();
    if (!fields) throw std::runtime_error("tabb dataset: malformed cali.txt line " + name);
    data.T_camera_target.push_back(TabbPose(R, t));
  }

  std::ifstream reference(dir + "rwhe_AA_RPI/transformations.txt");
  std::string label;
  reference >> label;  // "X"
  const Pose X_tabb = ReadTabbMatrix(reference);
  reference >> label >> label;  // "Z" "0"
  const Pose Z_tabb = ReadTabbMatrix(reference);
  data.X = Z_tabb.inverse();
  data.Z = X_tabb.inverse();
  if (data.T_base_gripper.size() != 88 || data.T_camera_target.size() != 88) {
    throw std::runtime_error("tabb dataset: expected 88 stations in " + dir);
  }
  return data;
}

}  // namespace hecal::testing
