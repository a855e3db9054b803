// The functions compiled once in dense_decompositions.cc and dense_decompositions_12.cc, against
// the definitions they compute: the four Moore–Penrose conditions of M⁺ on full-rank and
// rank-deficient matrices (the 12 × 12 hand–eye normal equations lose rank on degenerate
// motions), the minimum-norm least-squares solution, and the normal equations of a least-squares
// solve.
#include "hecal/geometry/dense_decompositions.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

#include "hecal/core/random_draws.h"

namespace hecal {
namespace {

// A rows × cols matrix of rank `rank` from a seeded product of two Gaussian factors.
Eigen::MatrixXd RankDeficient(int rows, int cols, int rank, unsigned seed) {
  std::mt19937 rng(seed);
  hecal::NormalDistribution normal;
  Eigen::MatrixXd left(rows, rank), right(rank, cols);
  for (double& v : left.reshaped()) v = normal(rng);
  for (double& v : right.reshaped()) v = normal(rng);
  return left * right;
}

// ‖M M⁺ M − M‖, ‖M⁺ M M⁺ − M⁺‖ and the asymmetry of M M⁺ and M⁺ M, relative to ‖M‖ and ‖M⁺‖.
void ExpectMoorePenrose(const Eigen::MatrixXd& M, const Eigen::MatrixXd& P) {
  const double m = M.norm(), p = P.norm();
  EXPECT_LT((M * P * M - M).norm(), 1e-10 * m);
  EXPECT_LT((P * M * P - P).norm(), 1e-10 * p);
  EXPECT_LT((M * P - (M * P).transpose()).norm(), 1e-10);
  EXPECT_LT((P * M - (P * M).transpose()).norm(), 1e-10);
}

TEST(DenseDecompositions, PseudoInverseMeetsTheMoorePenroseConditions) {
  for (int rank : {2, 5}) {
    const Eigen::MatrixXd M = RankDeficient(7, 5, rank, 3 + rank);
    const Eigen::MatrixXd P = PseudoInverse(M);
    ASSERT_EQ(P.rows(), 5);
    ASSERT_EQ(P.cols(), 7);
    ExpectMoorePenrose(M, P);
  }
}

TEST(DenseDecompositions, PseudoInverseOfAnInvertibleMatrixIsItsInverse) {
  const Eigen::MatrixXd M = RankDeficient(4, 4, 4, 9);
  EXPECT_LT((PseudoInverse(M) - M.inverse()).norm(), 1e-9 * M.inverse().norm());
}

TEST(DenseDecompositions, PseudoInverse12OfRankDeficientNormalEquations) {
  // Normal equations AᵀA of rank 9: three directions of X unobservable, as on parallel axes.
  const Eigen::MatrixXd A = RankDeficient(30, 12, 9, 21);
  const Eigen::Matrix<double, 12, 12> N = A.transpose() * A;
  const Eigen::Matrix<double, 12, 12> P = PseudoInverse12(N);
  ExpectMoorePenrose(N, P);
  EXPECT_LT((P - PseudoInverse(N)).norm(), 1e-9 * P.norm());
}

TEST(DenseDecompositions, PseudoSolve12IsTheMinimumNormLeastSquaresSolution) {
  const Eigen::MatrixXd A = RankDeficient(30, 12, 9, 22);
  const Eigen::Matrix<double, 12, 12> N = A.transpose() * A;
  Eigen::Matrix<double, 12, 1> b = N * Eigen::Matrix<double, 12, 1>::LinSpaced(1.0, 12.0);
  const Eigen::Matrix<double, 12, 1> x = PseudoSolve12(N, b);
  EXPECT_LT((N * x - b).norm(), 1e-9 * b.norm());                   // consistent: solved exactly
  EXPECT_LT((x - PseudoInverse12(N) * b).norm(), 1e-9 * x.norm());  // and of least norm
  // No component along the null space of N (the right singular vectors of A past its rank).
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  EXPECT_LT((svd.matrixV().rightCols(3).transpose() * x).norm(), 1e-9 * x.norm());
}

TEST(DenseDecompositions, ColPivQrSolveMeetsTheNormalEquations) {
  const Eigen::MatrixXd A = RankDeficient(20, 6, 6, 5);
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(20, -1.0, 2.0);
  const Eigen::VectorXd x = ColPivQrSolve(A, b);
  ASSERT_EQ(x.size(), 6);
  EXPECT_LT((A.transpose() * (A * x - b)).norm(), 1e-10 * A.norm() * b.norm());
  EXPECT_GT((A * x - b).norm(), 0.1);  // b is not in the range of A: a real least-squares case
}

}  // namespace
}  // namespace hecal
