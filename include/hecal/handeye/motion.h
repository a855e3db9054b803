// Relative motions for the AX = XB solvers, from ALL station pairs (issue 3).
//
// From Z = A_i X B_i = A_j X B_j (problem.h):   A_ij · X = X · B_ij   with
//        A_ij = A_j⁻¹ · A_i,      B_ij = B_j · B_i⁻¹.
// (Eye-in-hand: A_ij is the gripper motion, B_ij the camera motion — OpenCV's calibrateHandEye
// convention with X = cam2gripper.) Noise-free, A_ij and B_ij are conjugate: same rotation angle
// and same translation along the axis (the screw invariants Daniilidis checks).
// n stations give n(n−1)/2 motions; every solver accumulates its normal equations over them, so
// the cost is O(n²) small fixed-size operations and no large matrix is built.
#pragma once

#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"

namespace hecal::handeye {

struct Motion {
  Pose A;     // A_ij
  Pose B;     // B_ij
  int i = 0;  // station indices, i < j
  int j = 0;
};

std::vector<Motion> AllPairMotions(const Problem& problem);

}  // namespace hecal::handeye
