// The rigid-motion group SE(3) on Eigen::Isometry3d: exp, log, adjoint, Jacobians, interpolation.
//
// Tangent vectors are ξ = (ω, v): ROTATION FIRST (docs/conventions.md), ω in radians, v in metres.
// Right perturbation T = T̂ · Exp(δ); every 6×6 covariance in hecal uses this order and meaning.
//   Exp(ξ) = [ so3::Exp(ω)   Jl(ω)·v ]        Log is its inverse, |ω| ∈ [0, π]
//            [ 0             1        ]
//   Adjoint(T) = [ R      0 ]    so that T · Exp(δ) = Exp(Adjoint(T) δ) · T
//                [ [t]×R  R ]
//   RightJacobian Jr(ξ): Exp(ξ + δ) ≈ Exp(ξ) Exp(Jr(ξ) δ);  LeftJacobian Jl(ξ) = Jr(−ξ).
//   In (ω, v) order Jl(ξ) = [ Jl(ω) 0 ; Q(ω, v) Jl(ω) ] with Barfoot's Q (eq. 7.86 of Barfoot,
//   "State Estimation for Robotics", 2017, written there in (v, ω) order); Q uses series for
//   small |ω|.
//   Interpolate(T0, T1, s) = T0 · Exp(s · Log(T0⁻¹ T1)): the screw-motion geodesic.
// Composition and inverse are Isometry3d's own operator* and inverse().
#pragma once

#include "hecal/geometry/types.h"

namespace hecal::se3 {

Pose Exp(const Vector6d& xi);
Vector6d Log(const Pose& T);

Matrix6d Adjoint(const Pose& T);

Matrix6d RightJacobian(const Vector6d& xi);
Matrix6d RightJacobianInverse(const Vector6d& xi);
Matrix6d LeftJacobian(const Vector6d& xi);
Matrix6d LeftJacobianInverse(const Vector6d& xi);

Pose Interpolate(const Pose& T0, const Pose& T1, double s);

}  // namespace hecal::se3
