// The nearest rotation in the Frobenius norm: the SVD polar projection and the linear pose paper's
// quaternion-eigenvector form (eqs. 28–32) must agree, return rotations, and be optimal.
#include "hecal/geometry/nearest_rotation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "testing/random_poses.h"

namespace hecal {
namespace {

// Independent of so3.h: how far R is from SO(3) (orthonormality and det = +1).
double RotationError(const Eigen::Matrix3d& R) {
  return std::max((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(),
                  std::abs(R.determinant() - 1.0));
}

Eigen::Matrix3d RandomGaussianMatrix(std::mt19937_64& rng, double sigma) {
  hecal::NormalDistribution normal(0.0, sigma);
  Eigen::Matrix3d M;
  for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = normal(rng);
  return M;
}

// A small rotation about a random axis, built with Eigen (not the code under test).
Eigen::Matrix3d SmallRotation(std::mt19937_64& rng, double angle) {
  return Eigen::AngleAxisd(angle, testing::RandomUnitVector(rng)).toRotationMatrix();
}

// Sensitivity of the nearest rotation: it is unique and well conditioned when the two smallest
// singular values, combined as the projection needs, stay apart from zero: σ2 + σ3 for det > 0,
// σ2 − σ3 for det < 0 (the direction of σ3 is flipped).
double Conditioning(const Eigen::Matrix3d& M) {
  const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(M).singularValues();
  return M.determinant() >= 0.0 ? sigma(1) + sigma(2) : sigma(1) - sigma(2);
}

void ExpectBothNearest(const Eigen::Matrix3d& M, double agreement, const char* what) {
  const Eigen::Matrix3d A = NearestRotationSvd(M);
  const Eigen::Matrix3d B = NearestRotationQuaternion(M);
  EXPECT_LT(RotationError(A), 1e-14) << what << "\n" << M;
  EXPECT_LT(RotationError(B), 1e-14) << what << "\n" << M;
  EXPECT_LT((A - B).cwiseAbs().maxCoeff(), agreement) << what << "\n" << M;
}

TEST(NearestRotation, ExactRotationReturnsItself) {
  std::mt19937_64 rng(3);
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    const double theta = omega.norm();
    const Eigen::Matrix3d R = theta == 0.0
                                  ? Eigen::Matrix3d::Identity()
                                  : Eigen::AngleAxisd(theta, omega / theta).toRotationMatrix();
    EXPECT_LT((NearestRotationSvd(R) - R).cwiseAbs().maxCoeff(), 1e-14) << omega.transpose();
    EXPECT_LT((NearestRotationQuaternion(R) - R).cwiseAbs().maxCoeff(), 1e-14) << omega.transpose();
  }
  for (int n = 0; n < 1000; ++n) {
    const Eigen::Matrix3d R = testing::RandomRotation(rng);
    EXPECT_LT((NearestRotationSvd(R) - R).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_LT((NearestRotationQuaternion(R) - R).cwiseAbs().maxCoeff(), 1e-14);
  }
}

TEST(NearestRotation, ScaledRotationReturnsTheRotation) {
  std::mt19937_64 rng(5);
  for (const double scale : {1e-3, 0.5, 1.0, 2.0, 1e3}) {
    for (int n = 0; n < 200; ++n) {
      const Eigen::Matrix3d R = testing::RandomRotation(rng);
      const Eigen::Matrix3d M = scale * R;
      EXPECT_LT((NearestRotationSvd(M) - R).cwiseAbs().maxCoeff(), 1e-13) << scale;
      EXPECT_LT((NearestRotationQuaternion(M) - R).cwiseAbs().maxCoeff(), 1e-12) << scale;
    }
  }
}

TEST(NearestRotation, FormsAgreeOnPerturbedRotations) {
  std::mt19937_64 rng(7);
  for (const double sigma : {1e-9, 1e-6, 1e-3, 0.1, 0.3}) {
    for (int n = 0; n < 500; ++n) {
      // Drawn right to left: the order these tests' data were generated in.
      const Eigen::Matrix3d noise = RandomGaussianMatrix(rng, sigma);
      const Eigen::Matrix3d M = testing::RandomRotation(rng) + noise;
      ExpectBothNearest(M, 1e-10, "perturbed rotation");
    }
  }
}

TEST(NearestRotation, FormsAgreeOnGeneralMatrices) {
  std::mt19937_64 rng(11);
  int positive = 0, negative = 0;
  while (positive < 1000 || negative < 1000) {
    const Eigen::Matrix3d M = RandomGaussianMatrix(rng, 1.0);
    // Near-degenerate draws have (nearly) non-unique minimisers; both forms are then right but
    // need not agree. Agreement scales as rounding / conditioning.
    if (Conditioning(M) < 1e-2) continue;
    const bool det_positive = M.determinant() > 0.0;
    if (det_positive ? positive >= 1000 : negative >= 1000) continue;
    ++(det_positive ? positive : negative);
    ExpectBothNearest(M, 1e-10, det_positive ? "det > 0" : "det < 0");
    // The result is a rotation even for a reflection-like M: det = +1.
    EXPECT_GT(NearestRotationSvd(M).determinant(), 0.0);
    EXPECT_GT(NearestRotationQuaternion(M).determinant(), 0.0);
  }
}

TEST(NearestRotation, ReflectionsAndRankDeficientMatrices) {
  // diag(1, 1, −1): σ2 = σ3 with det < 0, so the minimiser is not unique (the identity and the
  // π turns about x and y all reach it); only the distance is checked against the minimum over
  // SO(3): ‖M − R‖² = 3 + 3 − 2 tr(RᵀM) with max tr(RᵀM) = σ1 + σ2 − σ3 = 1.
  const Eigen::Matrix3d M = Eigen::Vector3d(1, 1, -1).asDiagonal();
  for (const Eigen::Matrix3d& R : {NearestRotationSvd(M), NearestRotationQuaternion(M)}) {
    EXPECT_LT(RotationError(R), 1e-14);
    EXPECT_NEAR((M - R).squaredNorm(), 6.0 - 2.0 * 1.0, 1e-12);
  }
  // A distinct smallest singular value with det < 0: unique, diag(3, 2, −1) → identity.
  const Eigen::Matrix3d N = Eigen::Vector3d(3, 2, -1).asDiagonal();
  EXPECT_LT((NearestRotationSvd(N) - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((NearestRotationQuaternion(N) - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(),
            1e-14);
  // Rank one and zero: still a rotation, and no worse than the identity or a random rotation.
  std::mt19937_64 rng(13);
  const Eigen::Vector3d u = testing::RandomUnitVector(rng), v = testing::RandomUnitVector(rng);
  const std::vector<Eigen::Matrix3d> deficient = {u * v.transpose(), Eigen::Matrix3d::Zero()};
  for (const Eigen::Matrix3d& D : deficient) {
    for (const Eigen::Matrix3d& R : {NearestRotationSvd(D), NearestRotationQuaternion(D)}) {
      EXPECT_LT(RotationError(R), 1e-14);
      const double best = (D - R).norm();
      for (int n = 0; n < 100; ++n) {
        EXPECT_LE(best, (D - testing::RandomRotation(rng)).norm() + 1e-12);
      }
    }
  }
}

TEST(NearestRotation, IsNoFartherThanOtherRotations) {
  // Optimality: against many random rotations, and against small perturbations R* · ΔR of the
  // answer itself (a first-order test: any descent direction would show up here).
  std::mt19937_64 rng(17);
  for (int n = 0; n < 200; ++n) {
    const double sigma = n % 2 == 0 ? 0.2 : 1.0;
    const Eigen::Matrix3d noise = RandomGaussianMatrix(rng, sigma);  // before the rotation
    const Eigen::Matrix3d M =
        n % 2 == 0 ? Eigen::Matrix3d(testing::RandomRotation(rng) + noise) : noise;
    if (Conditioning(M) < 1e-2) continue;
    for (const Eigen::Matrix3d& best : {NearestRotationSvd(M), NearestRotationQuaternion(M)}) {
      const double d_best = (M - best).norm();
      for (int k = 0; k < 100; ++k) {
        EXPECT_LE(d_best, (M - testing::RandomRotation(rng)).norm());
      }
      for (const double angle : {1e-2, 1e-3, 1e-4}) {
        for (int k = 0; k < 20; ++k) {
          const Eigen::Matrix3d Q = best * SmallRotation(rng, angle);
          // The gain is second order, ~ angle² · conditioning; allow rounding only.
          EXPECT_LE(d_best, (M - Q).norm() + 1e-14) << angle;
        }
      }
    }
  }
}

TEST(NearestRotation, QuaternionFormMinimisesTheSeedObjective) {
  // The paper's objective Σ_i ‖m_i * q − q * e_i‖² over the columns equals ‖M − R(q)‖_F², so the
  // quaternion answer's objective must not exceed that of nearby unit quaternions.
  std::mt19937_64 rng(19);
  hecal::NormalDistribution normal;
  auto objective = [](const Eigen::Matrix3d& M, const Eigen::Quaterniond& q) {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Quaterniond m(0.0, M(0, i), M(1, i), M(2, i));
      const Eigen::Vector3d e_vec = Eigen::Vector3d::Unit(i);
      const Eigen::Quaterniond e(0.0, e_vec.x(), e_vec.y(), e_vec.z());
      const Eigen::Quaterniond lhs = m * q, rhs = q * e;
      sum += (lhs.coeffs() - rhs.coeffs()).squaredNorm();
    }
    return sum;
  };
  for (int n = 0; n < 200; ++n) {
    const Eigen::Matrix3d noise = RandomGaussianMatrix(rng, 0.3);  // before the rotation
    const Eigen::Matrix3d M = testing::RandomRotation(rng) + noise;
    const Eigen::Quaterniond q(NearestRotationQuaternion(M));
    const double f = objective(M, q);
    EXPECT_NEAR(f, (M - q.toRotationMatrix()).squaredNorm(), 1e-12);
    for (int k = 0; k < 50; ++k) {
      const double s3 = normal(rng), s2 = normal(rng), s1 = normal(rng), s0 = normal(rng);
      const Eigen::Vector4d step(s0, s1, s2, s3);
      const Eigen::Quaterniond other(Eigen::Vector4d(q.coeffs() + 1e-3 * step).normalized());
      EXPECT_LE(f, objective(M, other) + 1e-14);
    }
  }
}

}  // namespace
}  // namespace hecal
