// Tests for skew.h: Skew(a) b = a × b and Vee as its inverse (on the antisymmetric part).
#include "hecal/geometry/skew.h"

#include <gtest/gtest.h>

#include <random>

#include "hecal/core/random_draws.h"
#include "testing/random_poses.h"

namespace hecal {
namespace {

constexpr int kSkewSamples = 2000;

TEST(Skew, EntriesAreTheStandardHatMatrix) {
  Eigen::Matrix3d expected;
  expected << 0, -3, 2,  //
      3, 0, -1,          //
      -2, 1, 0;
  EXPECT_EQ(Skew(Eigen::Vector3d(1, 2, 3)), expected);
}

TEST(Skew, TimesVectorIsCrossProduct) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < kSkewSamples; ++i) {
    const Eigen::Vector3d a = testing::RandomGaussianVector(rng, 3.0);
    const Eigen::Vector3d b = testing::RandomGaussianVector(rng, 3.0);
    const Eigen::Vector3d cross = a.cross(b);  // Eigen's cross product: independent peer
    EXPECT_LT((Skew(a) * b - cross).norm(), 1e-15 * a.norm() * b.norm()) << a.transpose();
  }
  // Right-handed basis: x × y = z.
  EXPECT_EQ(Skew(Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ());
}

TEST(Skew, IsAntisymmetricAndSquaresToProjector) {
  std::mt19937_64 rng(12);
  for (int i = 0; i < kSkewSamples; ++i) {
    const Eigen::Vector3d a = testing::RandomGaussianVector(rng, 3.0);
    const Eigen::Matrix3d S = Skew(a);
    EXPECT_EQ(S.transpose(), -S);
    // [a]×² = a aᵀ − |a|² I.
    const Eigen::Matrix3d expected =
        a * a.transpose() - a.squaredNorm() * Eigen::Matrix3d::Identity();
    EXPECT_LT((S * S - expected).norm(), 1e-14 * a.squaredNorm());
  }
}

TEST(Skew, VeeInvertsSkewExactly) {
  std::mt19937_64 rng(13);
  for (int i = 0; i < kSkewSamples; ++i) {
    const Eigen::Vector3d a = testing::RandomGaussianVector(rng, 3.0);
    EXPECT_EQ(Vee(Skew(a)), a);
  }
}

TEST(Skew, VeeOfGeneralMatrixIsVeeOfAntisymmetricPart) {
  std::mt19937_64 rng(14);
  hecal::NormalDistribution normal;
  for (int i = 0; i < kSkewSamples; ++i) {
    Eigen::Matrix3d M;
    for (int k = 0; k < 9; ++k) M(k / 3, k % 3) = normal(rng);
    const Eigen::Matrix3d A = 0.5 * (M - M.transpose());
    // Read the antisymmetric part's entries directly (A(2,1), A(0,2), A(1,0)).
    const Eigen::Vector3d expected(A(2, 1), A(0, 2), A(1, 0));
    EXPECT_LT((Vee(M) - expected).norm(), 1e-15 * M.norm());
    // The symmetric part is invisible to Vee.
    EXPECT_LT(Vee(M + M.transpose()).norm(), 1e-15 * M.norm());
    EXPECT_LT((Skew(Vee(M)) - A).norm(), 1e-15 * M.norm());
  }
}

TEST(Skew, VeeOfRotationIsSinTimesAxis) {
  // For R = Exp(θ n), the antisymmetric part of R is sin θ [n]×: Vee(R) = sin θ n.
  std::mt19937_64 rng(15);
  for (int i = 0; i < kSkewSamples; ++i) {
    const Eigen::Vector3d n = testing::RandomUnitVector(rng);
    const double theta = hecal::UniformRealDistribution(0.0, 3.14)(rng);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, n).toRotationMatrix();
    EXPECT_LT((Vee(R) - std::sin(theta) * n).norm(), 1e-15);
  }
}

}  // namespace
}  // namespace hecal
