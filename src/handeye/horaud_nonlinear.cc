#include "hecal/handeye/horaud_nonlinear.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>

#include "hecal/core/error.h"
#include "hecal/geometry/quaternion_matrices.h"
#include "hecal/geometry/rotation.h"
#include "hecal/geometry/skew.h"
#include "hecal/handeye/horaud.h"
#include "hecal/handeye/kronecker.h"
#include "hecal/handeye/rotation_init.h"
#include "hecal/handeye/solver_support.h"

namespace hecal::handeye {
namespace {

using Vector7d = Eigen::Matrix<double, 7, 1>;
using Matrix7d = Eigen::Matrix<double, 7, 7>;
using Vector13d = Eigen::Matrix<double, 13, 1>;
using Matrix13d = Eigen::Matrix<double, 13, 13>;

constexpr double kResidualFloor = 1e-12;  // relative, on mean squared residuals
constexpr double kPenaltyFactor = 100.0;  // λ relative to the radial data curvature
constexpr int kMaxIterations = 100;
constexpr double kMinTranslationConditioning = 1e-12;

// R̃(q) with R̃(q) p = vector part of q p q̄, for any q = (w, v) (‖q‖² times a rotation).
Eigen::Matrix3d ScaledRotation(const Eigen::Vector4d& q) {
  const double w = q(0);
  const Eigen::Vector3d v = q.tail<3>();
  return (w * w - v.squaredNorm()) * Eigen::Matrix3d::Identity() + 2.0 * v * v.transpose() +
         2.0 * w * Skew(v);
}

// ∂ vec(R̃(q)) / ∂q.
Eigen::Matrix<double, 9, 4> ScaledRotationJacobian(const Eigen::Vector4d& q) {
  const double w = q(0);
  const Eigen::Vector3d v = q.tail<3>();
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 9, 4> J;
  J.col(0) = Vec(2.0 * w * I + 2.0 * Skew(v));
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d e = I.col(k);
    J.col(1 + k) =
        Vec(-2.0 * v(k) * I + 2.0 * (e * v.transpose() + v * e.transpose()) + 2.0 * w * Skew(e));
  }
  return J;
}

// The quadratic forms of (H2) and (H3), accumulated once over the motions.
struct QuadraticForms {
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();  // f₁ = qᵀAq
  Matrix13d H = Matrix13d::Zero();              // f₂ = zᵀHz, z = (vec R̃, t, 1)
  double rotation_magnitude = 0.0;              // Σ ‖v'_i‖²
  double rotation_magnitude_b = 0.0;            // Σ ‖v_i‖²
  double translation_magnitude = 0.0;           // Σ (‖p'_i‖² + ‖p_i‖²) / 2
  double translation_magnitude_b = 0.0;         // Σ ‖p_i‖²
};

QuadraticForms Accumulate(const std::vector<Motion>& motions, const Eigen::Matrix3d& R_start) {
  QuadraticForms forms;
  Eigen::Matrix3d pp = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 9, 3> pK = Eigen::Matrix<double, 9, 3>::Zero();
  Vector9d pp_prime = Vector9d::Zero();
  Eigen::Matrix3d KK = Eigen::Matrix3d::Zero();
  Eigen::Vector3d Kp_prime = Eigen::Vector3d::Zero();
  double p_prime_squared = 0.0;
  for (const Motion& motion : motions) {
    const AlignedQuaternions aligned = AlignQuaternions(motion, R_start);
    const Eigen::Vector4d v_prime(0.0, aligned.a.x(), aligned.a.y(), aligned.a.z());
    const Eigen::Vector4d v(0.0, aligned.b.x(), aligned.b.y(), aligned.b.z());
    const Eigen::Matrix4d M = QuaternionLeftMatrix(v_prime) - QuaternionRightMatrix(v);
    forms.A.noalias() += M.transpose() * M;
    forms.rotation_magnitude += v_prime.squaredNorm();
    forms.rotation_magnitude_b += v.squaredNorm();

    const Eigen::Matrix3d K = motion.A.linear() - Eigen::Matrix3d::Identity();
    const Eigen::Vector3d& p_prime = motion.A.translation();
    const Eigen::Vector3d& p = motion.B.translation();
    pp.noalias() += p * p.transpose();
    for (int k = 0; k < 3; ++k) {
      pK.middleRows<3>(3 * k) += p(k) * K;
      pp_prime.segment<3>(3 * k) += p(k) * p_prime;
    }
    KK.noalias() += K.transpose() * K;
    Kp_prime.noalias() += K.transpose() * p_prime;
    p_prime_squared += p_prime.squaredNorm();
    forms.translation_magnitude += 0.5 * (p_prime.squaredNorm() + p.squaredNorm());
    forms.translation_magnitude_b += p.squaredNorm();
  }
  // L_i = [p_iᵀ ⊗ I₃, −(K_i − I), −p'_i];  H = Σ L_iᵀ L_i, upper triangle then mirrored.
  Matrix13d& H = forms.H;
  for (int k = 0; k < 3; ++k) {
    for (int l = 0; l < 3; ++l) {
      H.block<3, 3>(3 * k, 3 * l) = pp(k, l) * Eigen::Matrix3d::Identity();
    }
  }
  H.block<9, 3>(0, 9) = -pK;
  H.block<9, 1>(0, 12) = -pp_prime;
  H.block<3, 3>(9, 9) = KK;
  H.block<3, 1>(9, 12) = Kp_prime;
  H(12, 12) = p_prime_squared;
  H = Matrix13d(H.selfadjointView<Eigen::Upper>());
  return forms;
}

Vector13d Stack(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  Vector13d z;
  z << Vec(R), t, 1.0;
  return z;
}

// t minimising f₂ for a fixed (scaled) rotation: H_tt t = −(H_tR vec R + H_t1).
Eigen::Vector3d BestTranslation(const Matrix13d& H, const Eigen::Matrix3d& R) {
  const Eigen::Matrix3d H_tt = H.block<3, 3>(9, 9);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(H_tt);
  if (!(eigen.eigenvalues()(0) > kMinTranslationConditioning * eigen.eigenvalues()(2))) {
    throw DegenerateError(
        "the translation of X along the common rotation axis (every motion rotates about "
        "parallel axes, or not at all)",
        "add stations whose relative rotations have different axes");
  }
  const Eigen::Vector3d rhs = -(H.block<3, 9>(9, 0) * Vec(R) + H.block<3, 1>(9, 12));
  return eigen.eigenvectors() *
         (eigen.eigenvectors().transpose() * rhs).cwiseQuotient(eigen.eigenvalues());
}

class Objective {
 public:
  Objective(const QuadraticForms& forms, double lambda1, double lambda2, double lambda)
      : forms_(forms), lambda1_(lambda1), lambda2_(lambda2), lambda_(lambda) {}

  double Evaluate(const Vector7d& x) const {
    const Eigen::Vector4d q = x.head<4>();
    const Vector13d z = Stack(ScaledRotation(q), x.tail<3>());
    const double radial = 1.0 - q.squaredNorm();
    return lambda1_ * q.dot(forms_.A * q) + lambda2_ * z.dot(forms_.H * z) +
           lambda_ * radial * radial;
  }

  // Gauss–Newton JᵀJ and Jᵀr of F = ‖r‖² (F's gradient is 2 Jᵀr).
  void Linearize(const Vector7d& x, Matrix7d* JtJ, Vector7d* Jtr) const {
    const Eigen::Vector4d q = x.head<4>();
    const Vector13d z = Stack(ScaledRotation(q), x.tail<3>());
    Eigen::Matrix<double, 13, 7> D = Eigen::Matrix<double, 13, 7>::Zero();
    D.block<9, 4>(0, 0) = ScaledRotationJacobian(q);
    D.block<3, 3>(9, 4) = Eigen::Matrix3d::Identity();
    const Eigen::Matrix<double, 13, 7> HD = forms_.H * D;
    *JtJ = lambda2_ * D.transpose() * HD;
    *Jtr = lambda2_ * HD.transpose() * z;
    JtJ->topLeftCorner<4, 4>() += lambda1_ * forms_.A + 4.0 * lambda_ * q * q.transpose();
    Jtr->head<4>() += lambda1_ * forms_.A * q - 2.0 * lambda_ * (1.0 - q.squaredNorm()) * q;
  }

 private:
  const QuadraticForms& forms_;
  double lambda1_;
  double lambda2_;
  double lambda_;
};

Vector7d LevenbergMarquardt(const Objective& objective, Vector7d x) {
  double cost = objective.Evaluate(x);
  double damping = 1e-4;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    Matrix7d JtJ;
    Vector7d Jtr;
    objective.Linearize(x, &JtJ, &Jtr);
    bool accepted = false;
    bool converged = false;
    for (int attempt = 0; attempt < 12 && !accepted; ++attempt) {
      Matrix7d augmented = JtJ;
      augmented.diagonal() += damping * JtJ.diagonal();
      const Vector7d step = -augmented.ldlt().solve(Jtr);
      if (!step.allFinite()) break;
      if (step.norm() <= 1e-15 * (x.norm() + 1e-15)) {
        converged = true;
        break;
      }
      const Vector7d candidate = x + step;
      const double candidate_cost = objective.Evaluate(candidate);
      if (candidate_cost < cost) {
        converged = cost - candidate_cost <= 1e-15 * cost;
        x = candidate;
        cost = candidate_cost;
        damping = std::max(damping / 3.0, 1e-12);
        accepted = true;
      } else {
        damping *= 4.0;
      }
    }
    if (converged || !accepted) break;
  }
  return x;
}

}  // namespace

Pose RefineHoraudNonlinear(const std::vector<Motion>& motions, const Pose& start) {
  RequireMotions(motions, 2);
  const QuadraticForms forms = Accumulate(motions, start.linear());
  const double n = static_cast<double>(motions.size());
  const Eigen::Vector4d q0 = ToWxyz(QuaternionFromMatrix(start.linear()));
  const Eigen::Vector3d t0 = BestTranslation(forms.H, start.linear());
  const Vector13d z0 = Stack(start.linear(), t0);
  const double rotation_variance =
      std::max(q0.dot(forms.A * q0), kResidualFloor * forms.rotation_magnitude) / n;
  const double translation_variance =
      std::max(z0.dot(forms.H * z0), kResidualFloor * forms.translation_magnitude) / n;
  if (!(rotation_variance > 0.0) || !(translation_variance > 0.0)) {
    throw DegenerateError("the hand-eye pose (every motion is the identity)",
                          "move the robot between stations");
  }
  const double lambda1 = 1.0 / rotation_variance;
  const double lambda2 = 1.0 / translation_variance;
  const double lambda = kPenaltyFactor * (lambda1 * forms.rotation_magnitude_b +
                                          lambda2 * forms.translation_magnitude_b);
  const Objective objective(forms, lambda1, lambda2, lambda);
  Vector7d x;
  x << q0, t0;
  x = LevenbergMarquardt(objective, x);
  const Eigen::Matrix3d R = ScaledRotation(x.head<4>().normalized());
  return MakePose(R, BestTranslation(forms.H, R));
}

Pose SolveHoraudNonlinear(const std::vector<Motion>& motions) {
  return RefineHoraudNonlinear(motions, SolveHoraud(motions));
}

}  // namespace hecal::handeye
