// Screw (Plücker) parameters of a rigid motion: Chasles' theorem. See screw.h for the formulas.
#include "hecal/geometry/screw.h"

#include <cmath>

#include "hecal/geometry/rotation.h"

namespace hecal {

Screw ScrewFromPose(const Pose& T) {
  const AxisAngle axis_angle = AxisAngleFromMatrix(T.linear());
  const Eigen::Vector3d t = T.translation();
  Screw screw;
  if (axis_angle.angle == 0.0) {
    // Pure translation: the axis is the translation direction through the origin.
    const double norm = t.norm();
    if (norm > 0.0) {
      screw.l = t / norm;
      screw.d = norm;
    }
    return screw;
  }
  const Eigen::Vector3d& l = axis_angle.axis;
  screw.l = l;
  screw.theta = axis_angle.angle;
  screw.d = l.dot(t);
  // The point of the axis nearest the origin is p = ½ (t⊥ + cot(θ/2) l × t⊥), t⊥ = t − d l; it
  // solves (I − R) p = t⊥ with p ⊥ l. Its moment p × l expands to the expression below.
  const double half = 0.5 * screw.theta;
  const double cot_half = std::cos(half) / std::sin(half);
  const Eigen::Vector3d t_perp = t - screw.d * l;
  const Eigen::Vector3d m = 0.5 * (t.cross(l) + cot_half * t_perp);
  // t_perp's rounding along l is amplified by cot(θ/2) ~ 2/θ; remove it so l · m = 0 to rounding.
  screw.m = m - l.dot(m) * l;
  return screw;
}

Pose PoseFromScrew(const Screw& screw) {
  const Eigen::Vector3d l = screw.l.normalized();
  const Eigen::Vector3d m = screw.m - l.dot(screw.m) * l;  // moment of a line is ⊥ its direction
  // Rotation θ about the line through p = l × m, then d along l:
  //   t = p − R p + d l = d l + sinθ m + (1 − cosθ) l × m   (using l × p = −m for l ⊥ m).
  const double half = 0.5 * screw.theta;
  const double s_half = std::sin(half);
  const double one_minus_cos = 2.0 * s_half * s_half;  // no cancellation at small θ
  const Eigen::Vector3d t = screw.d * l + std::sin(screw.theta) * m + one_minus_cos * l.cross(m);
  AxisAngle axis_angle;
  axis_angle.axis = l;
  axis_angle.angle = screw.theta;
  return MakePose(MatrixFromAxisAngle(axis_angle), t);
}

}  // namespace hecal
