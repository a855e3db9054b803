// Screw (Plücker) parameters of a rigid motion (Chasles): rotation θ about the line with unit
// direction l and moment m = p × l (p any point on the line), and translation d along it.
// The thesis' "angle-axis + translation → screw (l, m, θ, d)" helper
// (docs/handeye-methods.md#the-thesis-pipeline), and the parameters of Daniilidis' dual quaternion
// q̌ = (cos(θ̌/2), sin(θ̌/2) ľ), θ̌ = θ + εd, ľ = l + εm.
//
// From (R, t) with θ ∈ (0, π]: l = rotation axis, d = l·t, m = ½ (t × l + cot(θ/2) (t − d l)).
// Pure translation (θ = 0, t ≠ 0): l = t/|t|, d = |t|, m = 0 (the line through the origin).
// Identity: l = (1, 0, 0), θ = d = 0, m = 0. Near θ = 0 the line moves off to infinity (the
// moment grows as 1/θ): that is geometry, not a numerical defect; callers that need a smooth
// parameterisation use the twist (se3::Log) instead: se3::Log(T) = (θ l, θ m + d l).
// At θ = π the axis sign is the one AxisAngleFromMatrix picks (largest |component| positive);
// (l, m, d) and (−l, −m, −d) describe the same motion there.
// PoseFromScrew normalises l and ignores any component of m along l. It rotates θ about the
// line through p = l × m, then slides d along l: t = d l + sinθ m + (1 − cosθ) l × m.
#pragma once

#include <Eigen/Core>

#include "hecal/geometry/types.h"

namespace hecal {

struct Screw {
  Eigen::Vector3d l = Eigen::Vector3d::UnitX();  // unit direction of the axis
  Eigen::Vector3d m = Eigen::Vector3d::Zero();   // moment of the axis line, l · m = 0
  double theta = 0.0;                            // rotation about the axis, [0, π]
  double d = 0.0;                                // translation along the axis (pitch · θ)
};

Screw ScrewFromPose(const Pose& T);
Pose PoseFromScrew(const Screw& screw);

}  // namespace hecal
