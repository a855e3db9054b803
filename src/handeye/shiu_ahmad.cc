#include "hecal/handeye/shiu_ahmad.h"

#include <Eigen/Eigenvalues>

#include "hecal/core/error.h"
#include "hecal/geometry/nearest_rotation.h"
#include "hecal/geometry/skew.h"
#include "hecal/handeye/kronecker.h"
#include "hecal/handeye/rotation_init.h"
#include "hecal/handeye/translation.h"

namespace hecal::handeye {

Pose SolveShiuAhmad(const std::vector<Motion>& motions) {
  const Eigen::Matrix3d R0 = SignFreeRotation(motions);
  double weight_sum = 0.0;
  Matrix9d planes = Matrix9d::Zero();  // Σ ω ½ (v vᵀ + w wᵀ), (S2)
  Vector9d rhs = Vector9d::Zero();     // Σ ω u = Σ vec(a_v b_vᵀ)
  for (const Motion& motion : motions) {
    const AlignedQuaternions q = AlignQuaternions(motion, R0);
    const Eigen::Vector3d a = q.a.vec();
    const Eigen::Vector3d b = q.b.vec();
    const double norm_a = a.norm();
    const double norm_b = b.norm();
    if (norm_a == 0.0 || norm_b == 0.0) continue;  // identity rotation: no axis, no information
    Eigen::Matrix3d across_b = -b * (b.transpose() / norm_b);  // |b| (I − k_B k_Bᵀ)
    across_b.diagonal().array() += norm_b;
    Eigen::Matrix3d across_a = -a * (a.transpose() / norm_a);  // |a| (I − k_A k_Aᵀ)
    across_a.diagonal().array() += norm_a;
    AddKronecker(0.5 * across_b, across_a, &planes);
    AddKronecker(0.5 * Skew(b), Skew(a), &planes);
    rhs += Vec(a * b.transpose());
    weight_sum += norm_a * norm_b;
  }
  Matrix9d normal = -planes;
  normal.diagonal().array() += weight_sum;
  const Eigen::SelfAdjointEigenSolver<Matrix9d> eigen(normal);
  const Vector9d& lambda = eigen.eigenvalues();  // ascending
  if (!(lambda(0) > 1e-10 * lambda(8))) {
    throw DegenerateError(
        "the hand-eye rotation about the common rotation axis (Shiu-Ahmad: the solution families "
        "of all motions share a common direction, every motion rotates about parallel axes)",
        "add stations whose relative rotations have clearly different axes");
  }
  const Vector9d r =
      eigen.eigenvectors() * (eigen.eigenvectors().transpose() * rhs).cwiseQuotient(lambda);
  const Eigen::Matrix3d R_X = NearestRotationSvd(Unvec(r));
  return MakePose(R_X, SolveTranslation(motions, R_X));
}

}  // namespace hecal::handeye
