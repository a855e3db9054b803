#include "hecal/handeye/shah.h"

#include <Eigen/Eigenvalues>

#include "hecal/core/error.h"
#include "hecal/handeye/kronecker.h"
#include "hecal/handeye/solver_support.h"
#include "hecal/handeye/translation_xz.h"

namespace hecal::handeye {

Solution SolveShah(const Problem& problem) {
  RequireStations(problem, 3);
  Matrix9d K = Matrix9d::Zero();
  for (size_t i = 0; i < problem.A.size(); ++i) {
    AddKronecker(problem.B[i].linear().transpose(), problem.A[i].linear(), &K);
  }
  const Eigen::SelfAdjointEigenSolver<Matrix9d> eigen(K.transpose() * K);
  const Vector9d& mu = eigen.eigenvalues();  // ascending
  if (!((mu(8) - mu(7)) > kShahMinGap * mu(8))) {
    throw DegenerateError(
        "the rotations of X and Z about the common rotation axis (every relative robot rotation "
        "is about parallel axes, or there is none)",
        "add stations whose relative rotations have different axes");
  }
  const Vector9d v = eigen.eigenvectors().col(8);
  const Vector9d u = K * v;
  Solution solution;
  const Eigen::Matrix3d R_X = RotationFromSignFreeVec(v);
  const TranslationsXZ t = SolveTranslationsXZ(problem, R_X);
  solution.X = MakePose(R_X, t.t_X);
  solution.Z = MakePose(RotationFromSignFreeVec(u), t.t_Z);
  return solution;
}

}  // namespace hecal::handeye
