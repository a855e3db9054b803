#include "hecal/handeye/li.h"

#include <Eigen/Cholesky>

#include "hecal/core/error.h"
#include "hecal/geometry/nearest_rotation.h"
#include "hecal/handeye/kronecker.h"
#include "hecal/handeye/solver_support.h"
#include "hecal/handeye/translation_xz.h"

namespace hecal::handeye {
namespace {

using Matrix24d = Eigen::Matrix<double, 24, 24>;
using Vector24d = Eigen::Matrix<double, 24, 1>;

// Blocks of w = (vec R_X, vec R_Z, t_X, t_Z).
constexpr int kRX = 0;
constexpr int kRZ = 9;
constexpr int kTX = 18;
constexpr int kTZ = 21;

}  // namespace

Solution SolveLi(const Problem& problem) {
  RequireStations(problem, 3);
  const size_t n = problem.A.size();
  const double scale = TranslationScale(problem);

  Matrix9d K = Matrix9d::Zero();                 // Σ R_Bi ⊗ R_Aiᵀ = Σ R_Ciᵀ ⊗ R_Aiᵀ
  Eigen::Matrix3d tt = Eigen::Matrix3d::Zero();  // Σ t_Ci t_Ciᵀ
  Eigen::Matrix<double, 9, 3> tR = decltype(tR)::Zero();  // Σ t_Ci ⊗ R_Ai
  Eigen::Vector3d t_C_sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_A_sum = Eigen::Matrix3d::Zero();
  Vector9d tt_A = Vector9d::Zero();                  // Σ t_Ci ⊗ t_Ai
  Eigen::Vector3d R_At_A = Eigen::Vector3d::Zero();  // Σ R_Aiᵀ t_Ai
  Eigen::Vector3d t_A_sum = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Matrix3d& R_A = problem.A[i].linear();
    const Eigen::Matrix3d& R_B = problem.B[i].linear();
    const Eigen::Vector3d t_A = problem.A[i].translation() / scale;
    const Eigen::Vector3d t_C = -(R_B.transpose() * problem.B[i].translation()) / scale;
    AddKronecker(R_B, R_A.transpose(), &K);
    tt.noalias() += t_C * t_C.transpose();
    for (int k = 0; k < 3; ++k) {
      tR.middleRows<3>(3 * k) += t_C(k) * R_A;
      tt_A.segment<3>(3 * k) += t_C(k) * t_A;
    }
    t_C_sum += t_C;
    R_A_sum += R_A;
    R_At_A.noalias() += R_A.transpose() * t_A;
    t_A_sum += t_A;
  }

  const double count = static_cast<double>(n);
  const Eigen::Matrix3d I3 = Eigen::Matrix3d::Identity();
  Matrix24d N = Matrix24d::Zero();
  N.block<9, 9>(kRX, kRX) = count * Matrix9d::Identity();
  N.block<9, 9>(kRX, kRZ) = -K;
  N.block<9, 9>(kRZ, kRZ) = count * Matrix9d::Identity();
  for (int k = 0; k < 3; ++k) {
    for (int l = 0; l < 3; ++l) N.block<3, 3>(kRZ + 3 * k, kRZ + 3 * l) += tt(k, l) * I3;
    N.block<3, 3>(kRZ + 3 * k, kTZ) = t_C_sum(k) * I3;
  }
  N.block<9, 3>(kRZ, kTX) = -tR;
  N.block<3, 3>(kTX, kTX) = count * I3;
  N.block<3, 3>(kTX, kTZ) = -R_A_sum.transpose();
  N.block<3, 3>(kTZ, kTZ) = count * I3;
  Vector24d rhs = Vector24d::Zero();
  rhs.segment<9>(kRZ) = tt_A;
  rhs.segment<3>(kTX) = -R_At_A;
  rhs.segment<3>(kTZ) = t_A_sum;

  const Eigen::LDLT<Matrix24d, Eigen::Upper> ldlt(N);  // reads the upper triangle
  const Vector24d pivots = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() != Eigen::Success ||
      !(pivots.minCoeff() > kLiMinPivotRatio * pivots.maxCoeff())) {
    throw DegenerateError(
        "X and Z about and along the common rotation axis (every relative robot rotation is "
        "about parallel axes, or there is none)",
        "add stations whose relative rotations have different axes");
  }
  const Vector24d w = ldlt.solve(rhs);
  const Eigen::Matrix3d R_X = NearestRotationSvd(Unvec(w.segment<9>(kRX)));
  const Eigen::Matrix3d R_Z = NearestRotationSvd(Unvec(w.segment<9>(kRZ)));
  const TranslationsXZ t = SolveTranslationsXZ(problem, R_X);
  return Solution{MakePose(R_X, t.t_X), MakePose(R_Z, t.t_Z)};
}

}  // namespace hecal::handeye
