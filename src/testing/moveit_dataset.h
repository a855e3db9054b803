// Test support (not installed): the bundled real data set data/moveit-calibration (50 eye-to-hand
// pose pairs from moveit_calibration's solver test; see its SOURCE.md) as a hecal Problem, read
// with a small local parser so handeye tests do not depend on the io layer.
// pose_samples.json is a JSON array of samples [T_base_eef, T_camera_target], each a row-major
// 4×4 given as 4 row arrays, in metres; the file holds nothing but brackets, commas and numbers,
// so the numbers are read in order. Upstream expectation (SOURCE.md): X = T_base_camera with
// t ≈ (0.659, −0.249, 0.830) m and Eigen eulerAngles(0, 1, 2) ≈ (0.230, −2.540, 1.950) rad,
// each to isApprox(·, 0.01).
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"

namespace hecal::testing {

inline const Eigen::Vector3d kMoveItTranslation(0.659, -0.249, 0.830);
inline const Eigen::Vector3d kMoveItEulerXyz(0.230, -2.540, 1.950);

inline handeye::Problem LoadMoveItProblem() {
  std::ifstream file(std::string(HECAL_SOURCE_DIR) + "/data/moveit-calibration/pose_samples.json");
  if (!file) throw std::runtime_error("moveit dataset: cannot open pose_samples.json");
  std::stringstream buffer;
  buffer << file.rdbuf();
  std::string text = buffer.str();
  for (char& c : text) {
    if (c == '[' || c == ']' || c == ',') c = ' ';
  }
  std::istringstream numbers(text);
  std::vector<Pose> T_base_eef, T_camera_target;
  Eigen::Matrix4d M;
  while (true) {
    for (int k = 0; k < 16; ++k) numbers >> M(k / 4, k % 4);
    if (!numbers) break;
    (T_base_eef.size() == T_camera_target.size() ? T_base_eef : T_camera_target).push_back(Pose(M));
  }
  if (T_base_eef.size() != T_camera_target.size()) {
    throw std::runtime_error("moveit dataset: odd number of 4x4 matrices");
  }
  return handeye::MakeProblem(handeye::Setup::kEyeToHand, T_base_eef, T_camera_target);
}

}  // namespace hecal::testing
