#include "hecal/handeye/horaud.h"

#include <Eigen/Eigenvalues>

#include "hecal/core/error.h"
#include "hecal/geometry/quaternion_matrices.h"
#include "hecal/geometry/rotation.h"
#include "hecal/handeye/rotation_init.h"
#include "hecal/handeye/translation.h"

namespace hecal::handeye {

Pose SolveHoraud(const std::vector<Motion>& motions) {
  const Eigen::Matrix3d R0 = SignFreeRotation(motions);
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  for (const Motion& motion : motions) {
    const AlignedQuaternions q = AlignQuaternions(motion, R0);
    const Eigen::Matrix4d L =
        QuaternionLeftMatrix(ToWxyz(q.a)) - QuaternionRightMatrix(ToWxyz(q.b));
    A.noalias() += L.transpose() * L;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(A);
  const Eigen::Vector4d& lambda = eigen.eigenvalues();  // ascending
  if (!(lambda(1) - lambda(0) > 1e-12 * lambda(3))) {
    throw DegenerateError(
        "the hand-eye rotation about the common rotation axis (Horaud-Dornaika: the smallest "
        "eigenvalue of A is not separated, every motion rotates about parallel axes)",
        "add stations whose relative rotations have clearly different axes");
  }
  const Eigen::Matrix3d R_X = MatrixFromQuaternion(FromWxyz(eigen.eigenvectors().col(0)));
  return MakePose(R_X, SolveTranslation(motions, R_X));
}

}  // namespace hecal::handeye
