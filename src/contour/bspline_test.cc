// Closed uniform cubic B-splines: partition of unity, closure, C² continuity, control points ↔
// curve points, tangents against finite differences, bad input.
#include "hecal/contour/bspline.h"

#include <gtest/gtest.h>

#include <numbers>

#include "hecal/core/error.h"

namespace hecal::contour {
namespace {

Eigen::Matrix2Xd Ellipse(int n, double a, double b) {
  Eigen::Matrix2Xd Q(2, n);
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * std::numbers::pi * k / n;
    Q.col(k) << a * std::cos(t) + 0.3 * std::sin(2 * t), b * std::sin(t);
  }
  return Q;
}

TEST(ClosedBSpline, BasisIsAPartitionOfUnityWithFourWeights) {
  const ClosedBSpline curve(Ellipse(7, 3, 2));
  for (double s = -3.0; s < 10.0; s += 0.137) {
    const Eigen::RowVectorXd b = curve.Basis(s);
    EXPECT_NEAR(b.sum(), 1.0, 1e-14);
    EXPECT_LE((b.array() != 0.0).count(), 4);
    EXPECT_GE(b.minCoeff(), 0.0);
  }
}

TEST(ClosedBSpline, ClosedPeriodicAndSmooth) {
  const ClosedBSpline curve(Ellipse(9, 3, 2));
  const double n = curve.size();
  EXPECT_LT((curve.Point(0.0) - curve.Point(n)).norm(), 1e-13);
  EXPECT_LT((curve.Point(-0.25) - curve.Point(n - 0.25)).norm(), 1e-13);
  for (int knot = 0; knot < curve.size(); ++knot) {  // C¹ across knots; C⁰ trivially
    const double e = 1e-9;
    EXPECT_LT((curve.Point(knot - e) - curve.Point(knot + e)).norm(), 1e-8);
    EXPECT_LT((curve.Tangent(knot - e) - curve.Tangent(knot + e)).norm(), 1e-7);
  }
}

TEST(ClosedBSpline, TangentMatchesFiniteDifferences) {
  const ClosedBSpline curve(Ellipse(6, 5, 1));
  for (double s = 0.05; s < 6.0; s += 0.31) {
    const double h = 1e-6;
    const Eigen::Vector2d numeric = (curve.Point(s + h) - curve.Point(s - h)) / (2 * h);
    EXPECT_LT((curve.Tangent(s) - numeric).norm(), 1e-7);
    EXPECT_NEAR(curve.Normal(s).norm(), 1.0, 1e-14);
    EXPECT_NEAR(curve.Normal(s).dot(curve.Tangent(s)), 0.0, 1e-12);
  }
}

TEST(ClosedBSpline, KnotPointsAndInterpolationRoundTrip) {
  const Eigen::Matrix2Xd Q = Ellipse(8, 4, 3);
  const ClosedBSpline curve(Q);
  Eigen::Matrix2Xd knots(2, 8);
  for (int i = 0; i < 8; ++i) {
    knots.col(i) = curve.Point(i);
    const Eigen::Vector2d expected = (Q.col((i + 7) % 8) + 4 * Q.col(i) + Q.col((i + 1) % 8)) / 6;
    EXPECT_LT((knots.col(i) - expected).norm(), 1e-14);
  }
  const ClosedBSpline back = ClosedBSpline::Interpolating(knots);
  EXPECT_LT((back.control_points() - Q).norm(), 1e-12);
}

TEST(ClosedBSpline, OrientationAreaAndNormalDirection) {
  // Counter-clockwise (y up) circle of radius ~1: positive area, outward normal.
  const ClosedBSpline curve(Ellipse(12, 1, 1));
  EXPECT_GT(curve.SignedArea(), 0.0);
  const Eigen::Vector2d p = curve.Point(1.3);
  EXPECT_GT(curve.Normal(1.3).dot(p - curve.ControlCentroid()), 0.0);
  Eigen::Matrix2Xd reversed = curve.control_points().rowwise().reverse();
  EXPECT_LT(ClosedBSpline(reversed).SignedArea(), 0.0);
  EXPECT_EQ(curve.Sample(5).cols(), 60);
}

TEST(ClosedBSpline, BadInput) {
  EXPECT_THROW(ClosedBSpline(Eigen::Matrix2Xd::Zero(2, 3)), InputError);
  Eigen::Matrix2Xd Q = Ellipse(5, 1, 1);
  Q(1, 2) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(ClosedBSpline{Q}, InputError);
  EXPECT_THROW(ClosedBSpline::Interpolating(Q), InputError);
}

}  // namespace
}  // namespace hecal::contour
