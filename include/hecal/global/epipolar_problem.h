// The target-free hand–eye problem (docs/global.md): robot motions and, per motion, bearing
// pairs between the two images the camera took (Heller, Havlena, Pajdla, "A branch-and-bound
// algorithm for globally optimal hand-eye calibration", CVPR 2012, §3; TPAMI 38(5), 2016).
//
// Frames. Station j has a hand pose H_j: H_j = T_base_gripper_j eye-in-hand, and
// H_j = T_base_gripper_j⁻¹ eye-to-hand (then the scene moves with the gripper and the fixed camera
// sees it as a camera moving in the gripper frame — problem.h's mapping). The unknown is
// X = T_hand_camera: T_gripper_camera eye-in-hand, T_base_camera eye-to-hand (metres, radians).
// A motion from station f ("first") to station s ("second") has the hand motion
// B = H_f⁻¹ H_s and the camera motion A = X⁻¹ B X, i.e. (paper eq. 2, with R_X = Rᵀ)
//   R_A = Rᵀ R_B R,      t_A = Rᵀ((R_B − I) t + t_B),      (R, t) = X,
// where t_A is the second camera centre in the first camera's frame (metric: the robot's scale).
// A bearing pair (v, u) holds unit rays to one scene point from the first and the second camera.
//
// Error of one pair. The rays v and R_A u meet in front of both cameras iff t_A lies in the
// wedge cone{v, −R_A u}. The cheiral ray error is the smallest angle E such that rays within E
// of v and of R_A u meet in front of both cameras with baseline t_A:
//   E = min { ε : t_A ∈ cone( C(v, ε) ∪ C(−R_A u, ε) ) },  C(a, ε) = rays within ε of a,
// computed in closed form through the separating plane (duality): with ŵ = t_A/|t_A|,
//   sin E = max(0, max_{|q| = 1, q·ŵ ≥ 0} min(−q·v, q·R_A u)).
// Its sub-level sets are convex cones, so for a fixed rotation the L∞ problem in t is
// quasi-convex (what makes the per-cube linear programme of cube_feasibility.h a sound relaxation).
// For a correct match (t_A's projection inside the wedge) E ≤ |e|, the paper's angle between
// t_A and the epipolar plane, e = ∠(v × R_A u, t_A) − π/2 (PlaneAngle). t_A = 0 (a pure
// rotation about the camera centre) constrains nothing: both errors are 0.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"

namespace hecal::global {

struct BearingPair {
  Eigen::Vector3d first = Eigen::Vector3d::UnitZ();   // v: unit ray, first camera frame
  Eigen::Vector3d second = Eigen::Vector3d::UnitZ();  // u: unit ray, second camera frame
  int id = 0;                                         // the caller's name for the pair
};

struct EpipolarMotion {
  Pose hand = Pose::Identity();  // B = H_first⁻¹ H_second
  int first_station = 0;
  int second_station = 0;
  std::vector<BearingPair> pairs;
};

struct EpipolarProblem {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  std::vector<EpipolarMotion> motions;
};

// H_j for the setup (see above).
Pose HandPose(handeye::Setup setup, const Pose& T_base_gripper);

// The camera motion A = X⁻¹ B X of a hand motion B.
Pose CameraMotion(const Pose& X, const Pose& hand_motion);

// The cheiral ray error E (radians, in [0, π/2]) of rays `first` (v) and `second_rotated`
// (R_A u) with baseline `baseline` (t_A); all in the first camera's frame.
double CheiralRayError(const Eigen::Vector3d& first, const Eigen::Vector3d& second_rotated,
                       const Eigen::Vector3d& baseline);

// |e|, the angle between t_A and the epipolar plane span(v, R_A u) (radians, in [0, π/2]).
double PlaneAngle(const Eigen::Vector3d& first, const Eigen::Vector3d& second_rotated,
                  const Eigen::Vector3d& baseline);

// E of every pair under X, motion by motion; and the largest (the L∞ objective).
std::vector<std::vector<double>> RayErrors(const EpipolarProblem& problem, const Pose& X);
double MaxRayError(const EpipolarProblem& problem, const Pose& X);
// The largest |e| under X.
double MaxPlaneAngle(const EpipolarProblem& problem, const Pose& X);

int PairCount(const EpipolarProblem& problem);

}  // namespace hecal::global
