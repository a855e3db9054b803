#include "hecal/handeye/andreff.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "hecal/core/error.h"
#include "hecal/geometry/nearest_rotation.h"
#include "hecal/handeye/kronecker.h"
#include "hecal/handeye/solver_support.h"
#include "hecal/handeye/translation.h"

namespace hecal::handeye {
namespace {

using Matrix12d = Eigen::Matrix<double, 12, 12>;
using Vector12d = Eigen::Matrix<double, 12, 1>;

// The normal equations N w = g of (A1)+(A2) in the scaled units (step 1 of the header).
struct AndreffSystem {
  Matrix12d N = Matrix12d::Zero();  // upper triangle filled
  Vector12d g = Vector12d::Zero();
  double scale = 1.0;  // translations were divided by this
};

AndreffSystem BuildSystem(const std::vector<Motion>& motions) {
  const double n = static_cast<double>(motions.size());
  const double scale = TranslationScale(motions);

  const Eigen::Matrix3d I3 = Eigen::Matrix3d::Identity();
  Matrix9d S = Matrix9d::Zero();                          // Σ R_B ⊗ R_A
  Eigen::Matrix3d tt = Eigen::Matrix3d::Zero();           // Σ t_B t_Bᵀ
  Eigen::Matrix<double, 9, 3> tR = decltype(tR)::Zero();  // Σ t_B ⊗ (I − R_A)
  Eigen::Matrix3d RR = Eigen::Matrix3d::Zero();           // Σ (2I − R_A − R_Aᵀ)
  Vector9d g_R = Vector9d::Zero();                        // Σ t_B ⊗ t_A
  Eigen::Vector3d g_t = Eigen::Vector3d::Zero();          // Σ (I − R_A)ᵀ t_A
  for (const Motion& motion : motions) {
    const Eigen::Matrix3d& R_A = motion.A.linear();
    const Eigen::Vector3d t_A = motion.A.translation() / scale;
    const Eigen::Vector3d t_B = motion.B.translation() / scale;
    const Eigen::Matrix3d I_minus_R_A = I3 - R_A;
    AddKronecker(motion.B.linear(), R_A, &S);
    tt.noalias() += t_B * t_B.transpose();
    for (int k = 0; k < 3; ++k) {
      tR.middleRows<3>(3 * k) += t_B(k) * I_minus_R_A;
      g_R.segment<3>(3 * k) += t_B(k) * t_A;
    }
    RR.noalias() += I_minus_R_A.transpose() * I_minus_R_A;
    g_t.noalias() += I_minus_R_A.transpose() * t_A;
  }

  AndreffSystem system;
  system.scale = scale;
  Matrix12d& N = system.N;
  N.topLeftCorner<9, 9>() = 2.0 * n * Matrix9d::Identity() - S - S.transpose();
  for (int k = 0; k < 3; ++k) {
    for (int l = 0; l < 3; ++l) N.block<3, 3>(3 * k, 3 * l) += tt(k, l) * I3;
  }
  N.topRightCorner<9, 3>() = tR;
  N.bottomRightCorner<3, 3>() = RR;
  system.g << g_R, g_t;
  return system;
}

}  // namespace

Pose SolveAndreff(const std::vector<Motion>& motions) {
  RequireMotions(motions, 2);
  const AndreffSystem system = BuildSystem(motions);
  const Eigen::LDLT<Matrix12d, Eigen::Upper> ldlt(system.N);
  const Vector12d pivots = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() != Eigen::Success ||
      !(pivots.minCoeff() > kAndreffMinPivotRatio * pivots.maxCoeff())) {
    throw DegenerateError(
        "the hand-eye rotation about the common rotation axis and the translation along it "
        "(every motion rotates about parallel axes, or not at all)",
        "add stations whose relative rotations have different axes");
  }
  const Vector12d w = ldlt.solve(system.g);
  const Eigen::Matrix3d R_X = NearestRotationSvd(Unvec(w.head<9>()));
  return MakePose(R_X, SolveTranslation(motions, R_X));
}

Pose SolveAndreff(const std::vector<Motion>& motions, const TranslationFix& fix) {
  RequireMotions(motions, 2);
  const AndreffSystem system = BuildSystem(motions);
  // Equality-constrained least squares: [N e; eᵀ 0] [w; μ] = [g; value / scale].
  Eigen::Matrix<double, 13, 13> K = Eigen::Matrix<double, 13, 13>::Zero();
  K.topLeftCorner<12, 12>() = system.N.selfadjointView<Eigen::Upper>();
  K(9 + fix.axis, 12) = K(12, 9 + fix.axis) = 1.0;
  Eigen::Matrix<double, 13, 1> rhs;
  rhs << system.g, fix.value / system.scale;
  Eigen::FullPivLU<Eigen::Matrix<double, 13, 13>> lu(K);
  lu.setThreshold(kAndreffMinPivotRatio);
  if (!lu.isInvertible()) {
    throw DegenerateError(
        "the hand-eye rotation, even with " + ComponentName(fix.axis) +
            " of X given (the robot does not rotate, or does not also translate across its "
            "rotation axis)",
        "add stations that rotate by tens of degrees and move the robot across its rotation axis");
  }
  const Eigen::Matrix<double, 13, 1> w = lu.solve(rhs);
  const Eigen::Matrix3d R_X = NearestRotationSvd(Unvec(w.head<9>()));
  return MakePose(R_X, SolveTranslation(motions, R_X, fix));
}

}  // namespace hecal::handeye
