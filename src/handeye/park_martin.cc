#include "hecal/handeye/park_martin.h"

#include <Eigen/SVD>
#include <cmath>

#include "hecal/core/error.h"
#include "hecal/geometry/nearest_rotation.h"
#include "hecal/handeye/rotation_init.h"
#include "hecal/handeye/translation.h"

namespace hecal::handeye {
namespace {

// Rotation vector of the unit quaternion q WITHOUT making its sign canonical: angle
// 2 atan2(|q_v|, q_w) ∈ [0, 2π), so q and −q give the two representations θ n and
// (θ − 2π) n of the same rotation.
Eigen::Vector3d LogOfSignedQuaternion(const Eigen::Quaterniond& q) {
  const double s = q.vec().norm();
  if (s < 1e-8) {
    // θ/s → 2/w (1 − s²/(3w²)) as s → 0 with w ≈ ±1; s = 0 is the identity.
    return s == 0.0
               ? Eigen::Vector3d::Zero()
               : Eigen::Vector3d((2.0 / q.w()) * (1.0 - s * s / (3.0 * q.w() * q.w())) * q.vec());
  }
  return (2.0 * std::atan2(s, q.w()) / s) * q.vec();
}

}  // namespace

Pose SolveParkMartin(const std::vector<Motion>& motions) {
  const Eigen::Matrix3d R0 = SignFreeRotation(motions);
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();  // Σ β αᵀ
  for (const Motion& motion : motions) {
    const AlignedQuaternions q = AlignQuaternions(motion, R0);
    M.noalias() += LogOfSignedQuaternion(q.b) * LogOfSignedQuaternion(q.a).transpose();
  }
  const Eigen::Matrix3d Mt = M.transpose();
  const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(Mt).singularValues();
  if (!(sigma(1) > 1e-12 * sigma(0))) {
    throw DegenerateError(
        "the hand-eye rotation about the common rotation axis (Park-Martin: M = sum beta "
        "alpha^T has rank <= 1, every motion rotates about parallel axes)",
        "add stations whose relative rotations have clearly different axes");
  }
  const Eigen::Matrix3d R_X = NearestRotationSvd(Mt);  // (MᵀM)^(−1/2) Mᵀ
  return MakePose(R_X, SolveTranslation(motions, R_X));
}

}  // namespace hecal::handeye
