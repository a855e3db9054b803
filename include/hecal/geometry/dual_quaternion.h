// Dual quaternions q̌ = q + ε q' (ε² = 0) for rigid motions, with the API of the thesis'
// DualQuaternion.h (docs/handeye-methods.md#the-thesis-pipeline) and Daniilidis (1999), "Hand-eye
// calibration using dual quaternions", IJRR 18(3), §3.
//
// A pose (R, t) is the unit dual quaternion q̌ = q + ε ½ t q (q the Hamilton quaternion of R);
// composition of poses is the dual-quaternion product: DQ(T_a_b · T_b_c) = DQ(T_a_b) * DQ(T_b_c).
// q̌ and −q̌ are the same pose: FromPose returns the one with real().w() ≥ 0 (Canonical()), and
// IsSamePose compares up to that sign.
//
// Exp / Log: Log of a unit q̌ is the pure dual quaternion ½ (ω + ε v) where (ω, v) = se3::Log of
// the pose (rotation angle ≤ π, same sign rule at exactly π), i.e. ½ θ̌ ľ in screw terms; Exp is
// its inverse on pure dual quaternions (series near θ = 0). So Exp(Log(q̌)) = ±q̌ and
// Log(Exp(p̌)) = p̌ for |ω| < π. Both extend to any q̌ with non-zero real part through the dual
// scalar part: Log(q̌) = log|q̌| + Log(q̌/|q̌|), with log(a + εb) = ln a + ε b/a, and
// Exp(s + εs' + p̌) = eˢ (1 + εs') Exp(p̌).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "hecal/geometry/screw.h"
#include "hecal/geometry/types.h"

namespace hecal {

struct DualNumber {
  double real = 0.0;
  double dual = 0.0;
};

class DualQuaternion {
 public:
  // Identity.
  DualQuaternion();
  // From the two quaternions (no normalisation).
  DualQuaternion(const Eigen::Quaterniond& real, const Eigen::Quaterniond& dual);
  // From a rotation and a translation: q + ε ½ t q (q normalised first).
  DualQuaternion(const Eigen::Quaterniond& rotation, const Eigen::Vector3d& translation);

  static DualQuaternion Identity();
  static DualQuaternion Zero();
  static DualQuaternion FromPose(const Pose& T);
  // (cos(θ̌/2), sin(θ̌/2) ľ) with θ̌ = θ + εd, ľ = l + εm; l is normalised and the component of m
  // along l ignored, so the result is unit.
  static DualQuaternion FromScrew(const Screw& screw);

  const Eigen::Quaterniond& real() const { return real_; }
  const Eigen::Quaterniond& dual() const { return dual_; }

  // Quaternion conjugate of both parts: q* + ε q'*. For a unit q̌ this is the inverse.
  DualQuaternion Conjugate() const;
  // Multiplicative inverse of any q̌ with non-zero real part: q⁻¹ − ε q⁻¹ q' q⁻¹.
  DualQuaternion Inverse() const;
  // Dual-number norm |q| + ε (q·q')/|q|; (1, 0) for a unit dual quaternion.
  DualNumber Norm() const;
  // Divides by the dual norm, making |real| = 1 and real·dual = 0. Real part must be non-zero.
  void Normalize();
  DualQuaternion Normalized() const;
  // Sign choice real().w() > 0 (ties broken by the first non-zero component of the 8-vector
  // (w, x, y, z, w', x', y', z'), as for quaternions). Same pose, same Norm().
  DualQuaternion Canonical() const;

  // Exponential of a pure dual quaternion (zero scalar parts) and logarithm of a unit one; see the
  // file comment for the extension to non-zero scalar parts and non-unit q̌.
  DualQuaternion Exp() const;
  DualQuaternion Log() const;

  Eigen::Vector3d TransformPoint(const Eigen::Vector3d& p) const;   // R p + t
  Eigen::Vector3d TransformVector(const Eigen::Vector3d& v) const;  // R v

  Eigen::Quaterniond Rotation() const;  // the (normalised) real part
  // Vector part of 2 q' q⁻¹ (= 2 q' q* for a unit q̌); unchanged when q̌ is scaled by a dual
  // number, so it is the pose's translation even before Normalize().
  Eigen::Vector3d Translation() const;
  Eigen::Quaterniond TranslationQuaternion() const;  // (0, t)
  Eigen::Matrix4d ToMatrix() const;                  // homogeneous 4×4 of ToPose()
  Pose ToPose() const;                               // (Rotation(), Translation())
  // ScrewFromPose(ToPose()): the conventions of screw.h (identity, pure translation, θ = π).
  Screw ToScrew() const;

  DualQuaternion operator*(const DualQuaternion& other) const;
  DualQuaternion operator+(const DualQuaternion& other) const;
  DualQuaternion operator-(const DualQuaternion& other) const;
  DualQuaternion operator*(double scale) const;

  // 8-vector (w, x, y, z, w', x', y', z') and back; the layout Daniilidis' solver stacks.
  Eigen::Matrix<double, 8, 1> ToVector() const;
  static DualQuaternion FromVector(const Eigen::Matrix<double, 8, 1>& v);

  // Component-wise closeness up to the overall sign (q̌ ≡ −q̌).
  bool IsSamePose(const DualQuaternion& other, double tolerance) const;

 private:
  Eigen::Quaterniond real_;
  Eigen::Quaterniond dual_;
};

}  // namespace hecal
