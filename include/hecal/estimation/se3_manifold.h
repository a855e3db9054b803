// A pose as a Ceres parameter block, on the SE(3) manifold with the RIGHT perturbation of
// docs/conventions.md:   Plus(T, δ) = T · Exp(δ),   Minus(T₂, T₁) = Log(T₁⁻¹ · T₂),   δ = (ω, v).
//
// Ambient storage (7 doubles): [qx, qy, qz, qw, tx, ty, tz] — the unit quaternion of the rotation
// in Eigen's coefficient order, then the translation in metres.
//
// Jacobian convention ("lifted" tangent Jacobians). Ceres multiplies the ambient Jacobian a cost
// function returns (rows × 7) by PlusJacobian (7 × 6) to get the tangent Jacobian it solves with.
// Here PlusJacobian = [I₆; 0], and every hecal cost function returns as "ambient" Jacobian the
// analytic right-perturbation Jacobian ∂r/∂δ in its first six columns and zeros in the seventh, so
// the product is exactly ∂r/∂δ. (The seventh ambient coordinate then carries no derivative; Ceres
// only ever uses the product.) MinusJacobian = [I₆ 0] is its left inverse, as Ceres requires.
// This pairing is what lets the cost functions use se3's closed-form Jacobians instead of
// differentiating through the quaternion.
#pragma once

#include <ceres/manifold.h>

#include "hecal/geometry/types.h"

namespace hecal::estimation {

inline constexpr int kPoseAmbientSize = 7;
inline constexpr int kPoseTangentSize = 6;

// Writes T into 7 ambient doubles / reads it back (the quaternion is normalised on reading).
void PoseToParameters(const Pose& T, double* parameters);
Pose PoseFromParameters(const double* parameters);

class Se3RightManifold final : public ceres::Manifold {
 public:
  int AmbientSize() const override { return kPoseAmbientSize; }
  int TangentSize() const override { return kPoseTangentSize; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;
};

}  // namespace hecal::estimation
