// The fixed-size kernels (fixed_size_kernels.h) against Eigen's general paths.
#include "fixed_size_kernels.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <cmath>
#include <random>

#include "hecal/core/random_draws.h"

namespace hecal::estimation::internal {
namespace {

Eigen::Matrix<double, 6, 6> RandomCovariance(std::mt19937_64& rng, double condition) {
  hecal::NormalDistribution normal;
  Eigen::Matrix<double, 6, 6> M;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) M(r, c) = normal(rng);
  const Eigen::HouseholderQR<Eigen::Matrix<double, 6, 6>> qr(M);
  const Eigen::Matrix<double, 6, 6> Q = qr.householderQ();
  Eigen::Matrix<double, 6, 1> eigenvalues;
  for (int k = 0; k < 6; ++k) eigenvalues(k) = std::pow(condition, -k / 5.0);
  return Q * eigenvalues.asDiagonal() * Q.transpose();
}

// L⁻¹ · L = I for Cholesky factors of covariances up to a condition number of 10⁸ (rotation
// variances in rad² beside translation variances in m² of a precise robot).
TEST(FixedSizeKernels, LowerTriangularInverseInvertsCholeskyFactors) {
  std::mt19937_64 rng(3);
  for (double condition : {1.0, 1e4, 1e8}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::LLT<Eigen::Matrix<double, 6, 6>> llt(RandomCovariance(rng, condition));
      ASSERT_EQ(llt.info(), Eigen::Success);
      const Eigen::Matrix<double, 6, 6> L = llt.matrixL();
      const Eigen::Matrix<double, 6, 6> product = LowerTriangularInverse(llt.matrixLLT()) * L;
      EXPECT_LT((product - Eigen::Matrix<double, 6, 6>::Identity()).norm(), 1e-12 * condition)
          << "condition " << condition;
      // Only the lower triangle is read: the upper one of matrixLLT() holds other numbers.
      EXPECT_TRUE(LowerTriangularInverse(llt.matrixLLT())
                      .isApprox(L.triangularView<Eigen::Lower>().solve(
                                    Eigen::Matrix<double, 6, 6>::Identity()),
                                1e-9));
    }
  }
}

// H += w · Mᵀ M equals the dynamic-size product, and accumulates.
TEST(FixedSizeKernels, AddWeightedGramMatchesTheDenseProduct) {
  std::mt19937_64 rng(5);
  hecal::NormalDistribution normal;
  Eigen::Matrix<double, 12, 12> H = Eigen::Matrix<double, 12, 12>::Zero();
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(12, 12);
  for (int station = 0; station < 4; ++station) {
    Eigen::Matrix<double, 6, 12> M;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 12; ++c) M(r, c) = normal(rng);
    const double w = 0.25 + station;
    AddWeightedGram(M, w, &H);
    const Eigen::MatrixXd dynamic = M;
    expected += w * dynamic.transpose() * dynamic;
  }
  EXPECT_LT((H - expected).norm(), 1e-12 * expected.norm());
  EXPECT_EQ((H - H.transpose()).norm(), 0.0);
}

}  // namespace
}  // namespace hecal::estimation::internal
