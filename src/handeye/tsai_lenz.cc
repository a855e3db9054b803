#include "hecal/handeye/tsai_lenz.h"

#include <Eigen/Cholesky>
#include <cmath>

#include "hecal/core/error.h"
#include "hecal/geometry/rotation.h"
#include "hecal/handeye/rotation_init.h"
#include "hecal/handeye/translation.h"

namespace hecal::handeye {

Pose SolveTsaiLenz(const std::vector<Motion>& motions) {
  const Eigen::Matrix3d R0 = SignFreeRotation(motions);
  // Normal equations of (Tsai 12) in the pre-rotated frame: rows S x = r with S = skew(s),
  // s = P_A + P_B̃, r = P_B̃ − P_A, so SᵀS = |s|² I − s sᵀ and Sᵀ r = r × s.
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const Motion& motion : motions) {
    const AlignedQuaternions q = AlignQuaternions(motion, R0);
    const Eigen::Vector3d P_A = 2.0 * q.a.vec();
    const Eigen::Vector3d P_B = 2.0 * (R0 * q.b.vec());  // P of B̃ = R0 B R0ᵀ
    const Eigen::Vector3d s = P_A + P_B;
    normal.noalias() -= s * s.transpose();
    normal.diagonal().array() += s.squaredNorm();
    rhs += (P_B - P_A).cross(s);
  }
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(normal);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) {
    throw DegenerateError(
        "the hand-eye rotation (Tsai-Lenz: the axes P_A + P_B of all motions are parallel)",
        "add stations whose relative rotations have clearly different axes");
  }
  const Eigen::Vector3d P_prime = ldlt.solve(rhs);  // tan(θ̃/2) ñ
  // θ̃ = 2 atan|P'| (Tsai 13): q̃ = (cos(θ̃/2), sin(θ̃/2) ñ) = (1, P') / √(1 + |P'|²).
  const Eigen::Quaterniond q_tilde(1.0, P_prime.x(), P_prime.y(), P_prime.z());
  const Eigen::Matrix3d R_X = MatrixFromQuaternion(q_tilde) * R0;
  return MakePose(R_X, SolveTranslation(motions, R_X));
}

}  // namespace hecal::handeye
