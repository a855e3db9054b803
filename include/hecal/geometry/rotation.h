// Conversions between rotation representations. Every function here is total on valid input
// and exact (to rounding) near the identity and near π.
//
//   matrix       R ∈ SO(3)
//   quaternion   Hamilton, unit; canonical sign w ≥ 0 (at w = 0: first non-zero of x, y, z > 0)
//   rotvec       ω = θ n, θ ∈ [0, π]  (so3::Exp / so3::Log)
//   axis–angle   (n, θ), θ ∈ [0, π], |n| = 1; at θ = 0 the axis is (1, 0, 0) by convention
//   Tsai's modified Rodrigues vector  P = 2 sin(θ/2) n, |P| ≤ 2 (Tsai & Lenz 1989, eq. 5; the
//                the thesis; docs/handeye-methods.md#tsai-and-lenz). Note: "modified Rodrigues
//                parameters" elsewhere usually means tan(θ/4) n; hecal uses Tsai's form under the
//                name TsaiRodrigues.
// Euler angles are in euler.h. Matrix → quaternion uses Shepperd's method (largest diagonal
// pivot), so it is accurate for every rotation.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hecal {

// Quaternion sign convention: returns ±q with w > 0, or, when w == 0, with the first non-zero
// vector component positive. q and −q are the same rotation.
Eigen::Quaterniond CanonicalQuaternion(const Eigen::Quaterniond& q);

// Shepperd's method; the result is unit and canonical. R must be a rotation (not checked).
Eigen::Quaterniond QuaternionFromMatrix(const Eigen::Matrix3d& R);
// q need not be unit (it is normalised); q must not be zero (precondition).
Eigen::Matrix3d MatrixFromQuaternion(const Eigen::Quaterniond& q);

Eigen::Quaterniond QuaternionFromRotationVector(const Eigen::Vector3d& omega);
// Returns ω with |ω| ∈ [0, π] (the canonical quaternion's rotation).
Eigen::Vector3d RotationVectorFromQuaternion(const Eigen::Quaterniond& q);

struct AxisAngle {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // unit
  double angle = 0.0;                               // radians, [0, π]
};
AxisAngle AxisAngleFromMatrix(const Eigen::Matrix3d& R);
Eigen::Matrix3d MatrixFromAxisAngle(const AxisAngle& axis_angle);  // axis normalised first

// Tsai's P = 2 sin(θ/2) n. The inverse needs |P| ≤ 2 (values up to 2 + 1e-9 are clamped).
// Conditioning: |P| is flat in θ at π (it changes by only (π − θ)²/4), so P itself carries the
// angle there only to ~1e-16/cos(θ/2), at worst √ε ≈ 1.5e-8 rad at θ = π. MatrixFromTsaiRodrigues
// is exact to rounding away from π and within that bound near it (the one exception to "exact
// near π" above; it is the representation's, not the code's).
Eigen::Vector3d TsaiRodriguesFromMatrix(const Eigen::Matrix3d& R);
Eigen::Matrix3d MatrixFromTsaiRodrigues(const Eigen::Vector3d& P);

}  // namespace hecal
