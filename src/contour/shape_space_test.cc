// Shape space (docs/contour.md#shape-space): W S reproduces an affinity exactly, the fit inverts
// it, the fit covariance matches a sampled one, reduced spaces, degenerate contours.
#include "hecal/contour/shape_space.h"

#include <gtest/gtest.h>

#include <random>

#include "hecal/contour/contour_study.h"
#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"

namespace hecal::contour {
namespace {

Eigen::Matrix2Xd Affine(const Eigen::Matrix2Xd& Q, const Eigen::Matrix2d& M,
                        const Eigen::Vector2d& t) {
  return (M * Q).colwise() + t;
}

TEST(ShapeSpace, WOfTheSeedEncodesTheAffinity) {
  const Eigen::Matrix2Xd Q0 = DefaultTarget() * 1.2;
  const ShapeSpace space(Q0);
  Eigen::Matrix2d M;
  M << 1.1, -0.2, 0.05, 0.9;
  const Eigen::Vector2d t(3.0, -4.0);
  const Vector6d S = ShapeFromAffinity(M, t);
  EXPECT_EQ(S(2), 1.1 - 1.0);  // the paper's order (tx, ty, M11−1, M22−1, M21, M12)
  EXPECT_EQ(S(4), 0.05);
  EXPECT_EQ(S(5), -0.2);
  EXPECT_LT((space.Apply(S) - Affine(Q0, M, t)).norm(), 1e-12);
  EXPECT_LT((space.Fit(Affine(Q0, M, t)) - S).norm(), 1e-12);
  EXPECT_EQ(AffinityMatrix(S), M);
  EXPECT_EQ(AffinityTranslation(S), t);
}

TEST(ShapeSpace, FitCovarianceMatchesSampling) {
  const ShapeSpace space(DefaultTarget());
  std::mt19937_64 rng(3);
  hecal::NormalDistribution noise(0.0, 0.5);
  const int n = 20000;
  Eigen::MatrixXd samples(n, 6);
  for (int k = 0; k < n; ++k) {
    Eigen::Matrix2Xd Q = space.template_points();
    for (Eigen::Index i = 0; i < Q.size(); ++i) Q.data()[i] += noise(rng);
    samples.row(k) = space.Fit(Q).transpose();
  }
  const Eigen::MatrixXd centred = samples.rowwise() - samples.colwise().mean();
  const Eigen::MatrixXd sampled = centred.transpose() * centred / (n - 1);
  const Eigen::MatrixXd predicted = space.FitCovariance(0.5);
  for (int j = 0; j < 6; ++j) {
    EXPECT_NEAR(std::sqrt(sampled(j, j) / predicted(j, j)), 1.0, 0.02) << j;
  }
}

TEST(ShapeSpace, ReducedSpacesRepresentTheirMotions) {
  const Eigen::Matrix2Xd Q0 = DefaultTarget();
  // Similarity: M = s Rot(α) lies exactly in the 4-dim space.
  const ShapeSpace similarity(Q0, ShapeSubspace::kSimilarity);
  EXPECT_EQ(similarity.dim(), 4);
  const double s = 1.3, a = 0.7;
  Eigen::Matrix2d M;
  M << s * std::cos(a), -s * std::sin(a), s * std::sin(a), s * std::cos(a);
  const Eigen::Matrix2Xd image = Affine(Q0, M, Eigen::Vector2d(2, 3));
  const Eigen::VectorXd x = similarity.Fit(image);
  EXPECT_LT((similarity.Shape(x) - ShapeFromAffinity(M, Eigen::Vector2d(2, 3))).norm(), 1e-12);
  EXPECT_LT((similarity.Apply(x) - image).norm(), 1e-10);
  // Planar robot: tx, M11 − 1, M22 − 1.
  const ShapeSpace planar(Q0, ShapeSubspace::kPlanarRobot);
  Vector6d S;
  S << 4.0, 0.0, -0.2, 0.1, 0.0, 0.0;
  EXPECT_LT((planar.Shape(planar.Reduce(S)) - S).norm(), 1e-14);
  EXPECT_LT((planar.Shape(planar.Fit(ShapeSpace(Q0).Apply(S))) - S).norm(), 1e-12);
  EXPECT_EQ(ParseShapeSubspace("planar-robot"), ShapeSubspace::kPlanarRobot);
  EXPECT_EQ(ShapeSubspaceName(ShapeSubspace::kTranslationScale), "translation-scale");
  EXPECT_FALSE(ParseShapeSubspace("affine"));
}

TEST(ShapeSpace, CollinearOrCoincidentControlPointsAreDegenerate) {
  Eigen::Matrix2Xd line(2, 6);
  line << 0, 1, 2, 3, 4, 5, 1, 3, 5, 7, 9, 11;  // y = 2x + 1
  EXPECT_THROW(ShapeSpace{line}, DegenerateError);
  EXPECT_THROW(ShapeSpace(Eigen::Matrix2Xd::Ones(2, 6)), DegenerateError);
  // A line still determines a translation.
  EXPECT_NO_THROW(ShapeSpace(line, ShapeSubspace::kTranslation));
  EXPECT_THROW(ShapeSpace(Eigen::Matrix2Xd::Zero(2, 2)), InputError);
  const ShapeSpace space(DefaultTarget());
  EXPECT_THROW(space.Fit(Eigen::Matrix2Xd::Zero(2, 5)), InputError);
}

}  // namespace
}  // namespace hecal::contour
