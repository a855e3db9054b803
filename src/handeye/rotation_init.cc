#include "hecal/handeye/rotation_init.h"

#include <Eigen/Eigenvalues>

#include "hecal/core/error.h"
#include "hecal/geometry/rotation.h"
#include "hecal/handeye/kronecker.h"

namespace hecal::handeye {

Eigen::Matrix3d SignFreeRotation(const std::vector<Motion>& motions) {
  if (motions.empty()) {
    throw DegenerateError("the hand-eye rotation (no motions)", "use at least 3 stations");
  }
  Matrix9d S = Matrix9d::Zero();
  for (const Motion& motion : motions) {
    AddKronecker(motion.B.linear(), motion.A.linear(), &S);
  }
  const Eigen::SelfAdjointEigenSolver<Matrix9d> eigen(S + S.transpose());
  const Eigen::Matrix<double, 9, 1>& lambda = eigen.eigenvalues();  // ascending
  const double scale = 2.0 * static_cast<double>(motions.size());
  if ((lambda(8) - lambda(7)) < kSignFreeRotationMinGap * scale) {
    throw DegenerateError(
        "the hand-eye rotation about the common rotation axis and the translation along it "
        "(every motion rotates about parallel axes, or not at all)",
        "add stations whose relative rotations have different axes");
  }
  return RotationFromSignFreeVec(eigen.eigenvectors().col(8));
}

AlignedQuaternions AlignQuaternions(const Motion& motion, const Eigen::Matrix3d& R_X) {
  AlignedQuaternions result{QuaternionFromMatrix(motion.A.linear()),
                            QuaternionFromMatrix(motion.B.linear())};
  const double agreement = result.a.w() * result.b.w() + result.a.vec().dot(R_X * result.b.vec());
  if (agreement < 0.0) result.b.coeffs() = -result.b.coeffs();
  return result;
}

}  // namespace hecal::handeye
