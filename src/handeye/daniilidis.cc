#include "hecal/handeye/daniilidis.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "hecal/core/error.h"
#include "hecal/geometry/dual_quaternion.h"
#include "hecal/geometry/skew.h"
#include "hecal/handeye/rotation_init.h"
#include "hecal/handeye/solver_support.h"

namespace hecal::handeye {
namespace {

using Matrix34d = Eigen::Matrix<double, 3, 4>;
using Matrix8d = Eigen::Matrix<double, 8, 8>;
using Vector8d = Eigen::Matrix<double, 8, 1>;

// Below these the scalar-part residuals are rounding, whatever the robust scale says.
constexpr double kRotationResidualFloor = 1e-9;
constexpr double kTranslationResidualFloor = 1e-9;

// One motion's dual quaternions with consistent signs (translations normalised).
struct DualPair {
  Eigen::Quaterniond a, a_dual, b, b_dual;
};

Eigen::Quaterniond HalfTranslationTimes(const Eigen::Vector3d& t, const Eigen::Quaterniond& q) {
  Eigen::Quaterniond product = Eigen::Quaterniond(0.0, t.x(), t.y(), t.z()) * q;
  product.coeffs() *= 0.5;
  return product;
}

// [x_v − y_v, [x_v + y_v]×]: the vector part of x q − q y as a matrix acting on q (w, x, y, z).
Matrix34d DifferenceBlock(const Eigen::Quaterniond& x, const Eigen::Quaterniond& y) {
  Matrix34d M;
  M.col(0) = x.vec() - y.vec();
  M.rightCols<3>() = Skew(x.vec() + y.vec());
  return M;
}

// max(floor, factor · 1.4826 · median(values)); `values` is reordered.
double RobustTolerance(std::vector<double>& values, double floor) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return std::max(floor, kDaniilidisOutlierFactor * 1.4826 * *middle);
}

// λ = (λ₁, λ₂), |λ| = 1, with λᵀCλ = 0 (or closest to it) and the largest λᵀUλ.
Eigen::Vector2d ChooseRoot(const Eigen::Matrix2d& C, const Eigen::Matrix2d& U) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen;
  eigen.computeDirect(C);
  const double mu_low = eigen.eigenvalues()(0);
  const double mu_high = eigen.eigenvalues()(1);
  const Eigen::Vector2d e_low = eigen.eigenvectors().col(0);
  const Eigen::Vector2d e_high = eigen.eigenvectors().col(1);
  std::array<Eigen::Vector2d, 2> candidates;
  if (mu_low <= 0.0 && mu_high >= 0.0) {
    // (α e_low + β e_high)ᵀ C (…) = μ_low α² + μ_high β² = 0.
    const double alpha = std::sqrt(mu_high);
    const double beta = std::sqrt(-mu_low);
    candidates = {(alpha * e_low + beta * e_high).normalized(),
                  (alpha * e_low - beta * e_high).normalized()};
  } else {
    // Noise made C definite: no exact root; the eigenvector of the smaller |μ| is closest.
    const Eigen::Vector2d closest = std::abs(mu_low) < std::abs(mu_high) ? e_low : e_high;
    candidates = {closest, closest};
  }
  const double u0 = candidates[0].dot(U * candidates[0]);
  const double u1 = candidates[1].dot(U * candidates[1]);
  return u0 >= u1 ? candidates[0] : candidates[1];
}

}  // namespace

Pose SolveDaniilidis(const std::vector<Motion>& motions) {
  return SolveDaniilidis(motions, nullptr);
}

Pose SolveDaniilidis(const std::vector<Motion>& motions, DaniilidisReport* report) {
  RequireMotions(motions, 2);
  const Eigen::Matrix3d R_X0 = SignFreeRotation(motions);
  const double scale = TranslationScale(motions);

  const size_t n = motions.size();
  std::vector<DualPair> pairs(n);
  std::vector<double> rotation_residuals(n);
  std::vector<double> translation_residuals(n);
  for (size_t k = 0; k < n; ++k) {
    const AlignedQuaternions aligned = AlignQuaternions(motions[k], R_X0);
    DualPair& pair = pairs[k];
    pair.a = aligned.a;
    pair.b = aligned.b;
    pair.a_dual = HalfTranslationTimes(motions[k].A.translation() / scale, pair.a);
    pair.b_dual = HalfTranslationTimes(motions[k].B.translation() / scale, pair.b);
    rotation_residuals[k] = std::abs(pair.a.w() - pair.b.w());
    translation_residuals[k] = std::abs(pair.a_dual.w() - pair.b_dual.w());
  }
  std::vector<double> scratch = rotation_residuals;
  const double rotation_tolerance = RobustTolerance(scratch, kRotationResidualFloor);
  scratch = translation_residuals;
  const double translation_tolerance = RobustTolerance(scratch, kTranslationResidualFloor);

  Eigen::Matrix4d P = Eigen::Matrix4d::Zero();  // Σ M₁ᵀM₁
  Eigen::Matrix4d Q = Eigen::Matrix4d::Zero();  // Σ M₂ᵀM₂
  Eigen::Matrix4d C = Eigen::Matrix4d::Zero();  // Σ M₂ᵀM₁
  std::vector<int> rejected;
  for (size_t k = 0; k < n; ++k) {
    if (rotation_residuals[k] > rotation_tolerance ||
        translation_residuals[k] > translation_tolerance) {
      rejected.push_back(static_cast<int>(k));
      continue;
    }
    const Matrix34d M1 = DifferenceBlock(pairs[k].a, pairs[k].b);
    const Matrix34d M2 = DifferenceBlock(pairs[k].a_dual, pairs[k].b_dual);
    P.noalias() += M1.transpose() * M1;
    Q.noalias() += M2.transpose() * M2;
    C.noalias() += M2.transpose() * M1;
  }
  if (2 * rejected.size() > n) {
    throw DegenerateError(
        "a consistent hand-eye motion: " + std::to_string(rejected.size()) + " of " +
            std::to_string(n) +
            " motions have robot and camera rotation angles or screw pitches that disagree",
        "check the pose conventions (T_base_gripper, T_camera_target), the length units and the "
        "pairing of robot and camera rows");
  }

  Matrix8d TtT;
  TtT << P + Q, C, C.transpose(), P;
  const Eigen::SelfAdjointEigenSolver<Matrix8d> eigen(TtT);
  const Vector8d& lambda = eigen.eigenvalues();  // ascending
  Vector8d singular_values;
  for (int k = 0; k < 8; ++k) singular_values(k) = std::sqrt(std::max(lambda(7 - k), 0.0));
  if (report != nullptr) {
    report->singular_values = singular_values;
    report->rejected = rejected;
    report->rotation_tolerance = rotation_tolerance;
    report->translation_tolerance = translation_tolerance;
  }
  if (!(singular_values(5) > kDaniilidisRankTolerance * singular_values(0))) {
    throw DegenerateError(
        "the translation along the common rotation axis (the dual-quaternion system has rank "
        "5: every motion rotates about parallel axes)",
        "add stations whose relative rotations have different axes");
  }

  const Vector8d v7 = eigen.eigenvectors().col(1);
  const Vector8d v8 = eigen.eigenvectors().col(0);
  const Eigen::Vector4d u1 = v7.head<4>(), w1 = v7.tail<4>();
  const Eigen::Vector4d u2 = v8.head<4>(), w2 = v8.tail<4>();
  const double c12 = 0.5 * (u1.dot(w2) + u2.dot(w1));
  const Eigen::Matrix2d constraint{{u1.dot(w1), c12}, {c12, u2.dot(w2)}};
  const Eigen::Matrix2d real_norm{{u1.dot(u1), u1.dot(u2)}, {u1.dot(u2), u2.dot(u2)}};
  const Eigen::Vector2d lambda12 = ChooseRoot(constraint, real_norm);
  const Vector8d x = lambda12(0) * v7 + lambda12(1) * v8;

  const DualQuaternion solution = DualQuaternion(Eigen::Quaterniond(x(0), x(1), x(2), x(3)),
                                                 Eigen::Quaterniond(x(4), x(5), x(6), x(7)))
                                      .Normalized();
  return MakePose(solution.Rotation().toRotationMatrix(), scale * solution.Translation());
}

}  // namespace hecal::handeye
