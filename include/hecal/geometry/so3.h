// The rotation group SO(3): exponential and logarithm maps, Jacobians, adjoint, interpolation.
//
// Conventions (docs/conventions.md): rotation vectors ω in radians; right perturbation R = R̂ ·
// Exp(δ).
//   Exp(ω)           Rodrigues: I + sinθ/θ [ω]× + (1−cosθ)/θ² [ω]×², θ = |ω|
//   Log(R)           ω with |ω| ∈ [0, π], computed through the quaternion with atan2 so that it is
//                    accurate near 0 and near π (the trace formula loses all digits near π).
//                    At exactly π the sign of ω is ambiguous; Log returns the ω whose largest-
//                    magnitude component is positive (deterministic).
//   RightJacobian    Jr(ω): Exp(ω + δ) ≈ Exp(ω) · Exp(Jr(ω) δ)
//   LeftJacobian     Jl(ω): Exp(ω + δ) ≈ Exp(Jl(ω) δ) · Exp(ω);  Jl(ω) = Jr(−ω) = R Jr(ω)
//   Adjoint(R) = R:  R · Exp(δ) = Exp(R δ) · R
// References: Barfoot, "State Estimation for Robotics" (2017) §7.1; Solà, Deray, Atchuthan,
// "A micro Lie theory for state estimation in robotics" (2018), eqs. (143)–(146).
// Small angles use Taylor series (|θ| < 1e-4 or so) so no 0/0 occurs.
#pragma once

#include <Eigen/Core>

namespace hecal::so3 {

Eigen::Matrix3d Exp(const Eigen::Vector3d& omega);
Eigen::Vector3d Log(const Eigen::Matrix3d& R);

Eigen::Matrix3d RightJacobian(const Eigen::Vector3d& omega);
Eigen::Matrix3d RightJacobianInverse(const Eigen::Vector3d& omega);
Eigen::Matrix3d LeftJacobian(const Eigen::Vector3d& omega);
Eigen::Matrix3d LeftJacobianInverse(const Eigen::Vector3d& omega);

inline Eigen::Matrix3d Adjoint(const Eigen::Matrix3d& R) {
  return R;
}

// Geodesic interpolation R0 · Exp(s · Log(R0ᵀ R1)); s = 0 gives R0, s = 1 gives R1.
Eigen::Matrix3d Interpolate(const Eigen::Matrix3d& R0, const Eigen::Matrix3d& R1, double s);

// Rotation angle of R in [0, π], accurate over the whole range (atan2 of the quaternion parts).
double Angle(const Eigen::Matrix3d& R);

// Geodesic distance: angle of R_aᵀ R_b, in [0, π].
double Distance(const Eigen::Matrix3d& R_a, const Eigen::Matrix3d& R_b);

// How far M is from a rotation: max(|MᵀM − I| entries, |det M − 1|). 0 for an exact rotation.
double OrthonormalityError(const Eigen::Matrix3d& M);

}  // namespace hecal::so3
