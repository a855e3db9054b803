#include "hecal/contour/shape_tracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "hecal/contour/render.h"
#include "hecal/core/error.h"
#include "testing/options_validity.h"

namespace hecal::contour {
namespace {

// A bright asymmetric 8-point contour (pixels) around (80, 60) on a dark 160 × 120 image.
Eigen::Matrix2Xd Contour() {
  Eigen::Matrix2Xd q(2, 8);
  for (int k = 0; k < 8; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 8;
    const double rho = 1.0 + 0.2 * std::cos(2 * a) + 0.1 * std::sin(3 * a);
    q.col(k) << 80.0 + 45.0 * rho * std::cos(a), 60.0 + 32.0 * rho * std::sin(a);
  }
  return q;
}

GrayImage Render(const Eigen::Matrix2Xd& control_points, double noise, std::uint64_t seed) {
  RenderOptions options;
  options.noise_sigma = noise;
  options.seed = seed;
  return RenderPolygon(ClosedBSpline(control_points).Sample(48), 160, 120, options);
}

const Eigen::Vector2d kOrigin(80.0, 60.0);

TEST(ShapeTracker, TheTemplateViewGivesZeroMotionAndItsOwnUncertainty) {
  ShapeTracker tracker(Contour(), kOrigin);
  const TrackedFrame first = tracker.Track(Render(Contour(), 2.0, 1));
  EXPECT_TRUE(first.updated);
  EXPECT_EQ(first.frame, 0);
  EXPECT_EQ(first.edges_searched, 8 * 8);
  EXPECT_GE(first.edges_used, 60);
  EXPECT_EQ(first.shape, Vector6d::Zero());
  EXPECT_LT(first.shape_covariance.norm(), 1e-12);  // the motion since the first view: none
  EXPECT_GT(first.x_covariance.norm(), 0.0);        // the template's own fit error
  // The refined template is the given one up to a small fraction of a pixel.
  EXPECT_LT(tracker.template_shape().head<2>().norm(), 0.1);
  EXPECT_LT(tracker.template_shape().tail<4>().norm(), 2e-3);
  EXPECT_TRUE(first.sigma_estimated);
  EXPECT_GT(first.sigma, 0.01);
  EXPECT_LT(first.sigma, 0.2);
  // A bright target: the gradient along the outward normal is negative (bright → dark); the
  // normal of this counter-clockwise-on-screen contour points inwards, so the polarity is +1
  // or −1 consistently — it is learnt either way.
  EXPECT_NE(tracker.polarity(), 0);

  // A second, identical view: no motion, within the reported σ.
  const TrackedFrame second = tracker.Track(Render(Contour(), 2.0, 2));
  const Vector6d z = second.shape.cwiseQuotient(second.shape_covariance.diagonal().cwiseSqrt());
  EXPECT_LT(z.cwiseAbs().maxCoeff(), 4.0) << z.transpose();
}

TEST(ShapeTracker, FollowsATranslationAndScaling) {
  ShapeTracker tracker(Contour(), kOrigin);
  TrackedFrame frame;
  for (int t = 0; t < 8; ++t) {
    const double scale = 1.0 + 0.01 * t;
    const Eigen::Vector2d shift(2.5 * t, -1.5 * t);
    const Eigen::Matrix2Xd moved =
        ((scale * (Contour().colwise() - kOrigin)).colwise() + (kOrigin + shift));
    frame = tracker.Track(Render(moved, 2.0, 10 + static_cast<std::uint64_t>(t)));
    ASSERT_TRUE(frame.updated) << t;
    // d' = M d + t with d relative to the origin: t = shift, M = scale·I.
    Vector6d truth;
    truth << shift.x(), shift.y(), scale - 1.0, scale - 1.0, 0.0, 0.0;
    if (t == 0) continue;
    const Vector6d z =
        (frame.shape - truth).cwiseQuotient(frame.shape_covariance.diagonal().cwiseSqrt());
    EXPECT_LT(z.cwiseAbs().maxCoeff(), 4.5) << t << ": " << z.transpose();
    EXPECT_LT((frame.shape - truth).head<2>().norm(), 0.1) << t;
  }
  // The constant-velocity state has learnt the motion per frame.
  EXPECT_NEAR(frame.velocity(0), 2.5, 0.3);
  EXPECT_NEAR(frame.velocity(1), -1.5, 0.3);
}

TEST(ShapeTracker, ReducedSubspaceAndGivenSigma) {
  ShapeTrackerOptions options;
  options.subspace = ShapeSubspace::kTranslation;
  options.measurement_sigma = 0.3;
  options.refine_template = false;
  ShapeTracker tracker(Contour(), kOrigin, options);
  EXPECT_EQ(tracker.space().dim(), 2);
  const Eigen::Matrix2Xd moved = Contour().colwise() + Eigen::Vector2d(1.7, 0.6);
  const TrackedFrame frame = tracker.Track(Render(moved, 1.0, 3));
  ASSERT_TRUE(frame.updated);
  EXPECT_EQ(frame.x.size(), 2);
  EXPECT_FALSE(frame.sigma_estimated);
  EXPECT_DOUBLE_EQ(frame.sigma, 0.3);
  EXPECT_NEAR(frame.shape(0), 1.7, 0.1);
  EXPECT_NEAR(frame.shape(1), 0.6, 0.1);
  EXPECT_EQ(frame.shape.tail<4>(), Eigen::Vector4d::Zero());
  // Without refinement the first frame is measured like any other; with a given σ the
  // covariance is σ² (Σ hᵀh)⁻¹ combined with the wide prior: about σ / √(m/2) per axis.
  const double sd = std::sqrt(frame.shape_covariance(0, 0));
  EXPECT_GT(sd, 0.3 / std::sqrt(frame.edges_used));
  EXPECT_LT(sd, 0.3 / std::sqrt(frame.edges_used / 4.0));
}

TEST(ShapeTracker, AnEmptyImageKeepsThePrediction) {
  ShapeTracker tracker(Contour(), kOrigin);
  ASSERT_TRUE(tracker.Track(Render(Contour(), 1.0, 4)).updated);
  const TrackedFrame lost = tracker.Track(GrayImage(160, 120, 60.0f));
  EXPECT_FALSE(lost.updated);
  EXPECT_EQ(lost.edges_used, 0);
  EXPECT_LT(lost.shape.norm(), 1e-9);             // zero velocity: the prediction stays put
  EXPECT_GT(lost.shape_covariance.trace(), 0.5);  // … but grows uncertain
  EXPECT_TRUE(tracker.Track(Render(Contour(), 1.0, 5)).updated);  // and recovers
}

TEST(ShapeTracker, RejectsDegenerateContoursAndBadOptions) {
  Eigen::Matrix2Xd line(2, 5);
  line << 0, 10, 20, 30, 40,  //
      0, 5, 10, 15, 20;
  EXPECT_THROW(ShapeTracker(line, kOrigin), DegenerateError);
  ShapeTrackerOptions options;
  options.points_per_span = 0;
  EXPECT_THROW(ShapeTracker(Contour(), kOrigin, options), InputError);
  options = {};
  options.measurement_sigma = -1.0;
  EXPECT_THROW(ShapeTracker(Contour(), kOrigin, options), InputError);
  EXPECT_THROW(ShapeTracker(Contour(), Eigen::Vector2d(NAN, 0.0)), InputError);
}

TEST(ShapeTrackerOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const ShapeTrackerOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.subspace",
                            [](auto& o) { o.subspace = static_cast<ShapeSubspace>(99); }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.points_per_span",
                            [](auto& o) { o.points_per_span = 0; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "EdgeSearchOptions.step", [](auto& o) { o.search.step = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.iterations",
                            [](auto& o) { o.iterations = 101; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.gate", [](auto& o) { o.gate = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.measurement_sigma",
                            [](auto& o) { o.measurement_sigma = -1.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.sigma_floor",
                            [](auto& o) { o.sigma_floor = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.initial_measurement_sigma",
                            [](auto& o) { o.initial_measurement_sigma = -2.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.process_noise", [](auto& o) {
    o.process_noise = std::numeric_limits<double>::infinity();
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.initial_sigma",
                            [](auto& o) { o.initial_sigma = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ShapeTrackerOptions.initial_velocity_sigma",
                            [](auto& o) { o.initial_velocity_sigma = 0.0; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "ShapeTrackerOptions.min_edges", [](auto& o) { o.min_edges = -1; }));
}

}  // namespace
}  // namespace hecal::contour
