#include "hecal/handeye/translation_xz.h"

#include <Eigen/Eigenvalues>

#include "hecal/core/error.h"

namespace hecal::handeye {

TranslationsXZ SolveTranslationsXZ(const Problem& problem, const Eigen::Matrix3d& R_X) {
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  Eigen::Vector3d g_X = Eigen::Vector3d::Zero();
  Eigen::Vector3d g_Z = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < problem.A.size(); ++i) {
    const Eigen::Matrix3d& R_A = problem.A[i].linear();
    const Eigen::Vector3d d = R_A * (R_X * problem.B[i].translation()) + problem.A[i].translation();
    M += R_A;
    g_X.noalias() -= R_A.transpose() * d;
    g_Z += d;
  }
  const double n = static_cast<double>(problem.A.size());
  const Eigen::Matrix3d schur = n * Eigen::Matrix3d::Identity() - M.transpose() * M / n;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(schur);
  if (!(eigen.eigenvalues()(0) > kTranslationXZMinConditioning * n)) {
    throw DegenerateError(
        "the translations of X and Z along the common rotation axis (every relative robot "
        "rotation is about parallel axes, or there is none)",
        "add stations whose relative rotations have different axes");
  }
  TranslationsXZ result;
  const Eigen::Vector3d rhs = g_X + M.transpose() * g_Z / n;
  result.t_X = eigen.eigenvectors() *
               (eigen.eigenvectors().transpose() * rhs).cwiseQuotient(eigen.eigenvalues());
  result.t_Z = (g_Z + M * result.t_X) / n;
  return result;
}

}  // namespace hecal::handeye
