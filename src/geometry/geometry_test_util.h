// Test support for the geometry tests: the small independent helpers several of them share
// (entry-wise distances, the quaternion as a (w, x, y, z) vector, elementary rotations written
// out from cos/sin, angle differences modulo 2π and the 24 Euler sequences).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"

namespace hecal {

// The largest absolute entry of M.
inline double MaxAbs(const Eigen::MatrixXd& M) {
  return M.cwiseAbs().maxCoeff();
}

// The largest entry-wise difference of the 4×4 matrices.
inline double PoseError(const Pose& A, const Pose& B) {
  return MaxAbs(A.matrix() - B.matrix());
}

inline Eigen::Vector4d Wxyz(const Eigen::Quaterniond& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}

// Elementary rotation about coordinate axis `axis` (0, 1, 2), written out from cos/sin.
inline Eigen::Matrix3d Elementary(int axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  R(i, i) = c;
  R(i, j) = -s;
  R(j, i) = s;
  R(j, j) = c;
  return R;
}

// |a − b| modulo 2π, in [0, π].
inline double AngleDifference(double a, double b) {
  return std::abs(std::remainder(a - b, 2.0 * std::numbers::pi));
}

// The 24 Euler sequences: the 12 extrinsic ("xyz", lower case), then the 12 intrinsic ("XYZ").
inline std::vector<std::string> AllSequences() {
  std::vector<std::string> sequences;
  for (const bool upper : {false, true}) {
    for (const char a : {'x', 'y', 'z'}) {
      for (const char b : {'x', 'y', 'z'}) {
        for (const char c : {'x', 'y', 'z'}) {
          if (a == b || b == c) continue;
          std::string s{a, b, c};
          if (upper) {
            for (char& ch : s) ch = static_cast<char>(std::toupper(ch));
          }
          sequences.push_back(s);
        }
      }
    }
  }
  return sequences;
}

}  // namespace hecal
