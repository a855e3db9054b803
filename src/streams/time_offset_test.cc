#include "hecal/streams/time_offset.h"

#include <gtest/gtest.h>

#include <cmath>

#include "hecal/geometry/se3.h"

namespace hecal::streams {
namespace {

// A profile with a known answer: χ²(δ) = c₀ + ((δ − δ₀)/σ)², X(δ) = X₀·Exp(b_X (δ − δ₀)),
// Z(δ) = Z₀·Exp(b_Z (δ − δ₀)).
struct Known {
  double best = 0.0123;
  double sigma = 0.0007;
  Vector6d bx = (Vector6d() << 0.1, -0.2, 0.3, 0.01, 0.02, -0.03).finished();
  Vector6d bz = (Vector6d() << -0.05, 0.0, 0.2, 0.5, -0.1, 0.0).finished();
  Pose X0 = se3::Exp((Vector6d() << 0.3, 0.2, 0.1, 0.05, 0.0, 0.1).finished());
  Pose Z0 = se3::Exp((Vector6d() << -0.1, 0.4, 0.0, 0.5, 0.3, 0.2).finished());
  int calls = 0;
  ProfilePoint operator()(double offset) {
    ++calls;
    const double d = offset - best;
    return {.cost = 100.0 + d * d / (sigma * sigma),
            .X = X0 * se3::Exp(bx * d),
            .Z = Z0 * se3::Exp(bz * d)};
  }
};

TEST(TimeOffset, FindsTheMinimumAnywhereInTheWindow) {
  for (double best : {-0.93, -0.2, 0.0123, 0.5, 0.97}) {
    Known profile;
    profile.best = best;
    // A start far off (the speed correlation's value on slow motion).
    const OffsetMinimum found = MinimiseProfile(std::ref(profile), -best, -1.0, 1.0, 0.067, 1e-6);
    EXPECT_NEAR(found.offset, best, 1e-5) << best;
    EXPECT_FALSE(found.on_edge);
    EXPECT_EQ(found.evaluations, profile.calls);
    EXPECT_LT(found.evaluations, 80);
  }
  Known outside;
  outside.best = 1.4;
  EXPECT_TRUE(MinimiseProfile(std::ref(outside), 0.0, -1.0, 1.0, 0.067, 1e-6).on_edge);
}

TEST(TimeOffset, SigmaFromTheCurvatureAndTheSlopeOfTheOptimum) {
  Known profile;
  const ProfilePoint at = profile(profile.best);
  for (double step : {1e-5, 1e-3, 0.1}) {  // the step adapts to a rise of about 4
    const OffsetUncertainty u = ProfileUncertainty(std::ref(profile), profile.best, at, step);
    ASSERT_TRUE(u.curved);
    EXPECT_NEAR(u.sigma, profile.sigma, 1e-3 * profile.sigma) << step;
    EXPECT_LT((u.slope.head<6>() - profile.bx).norm(), 1e-3) << step;
    EXPECT_LT((u.slope.tail<6>() - profile.bz).norm(), 1e-3) << step;
    EXPECT_TRUE(
        u.added.isApprox(u.slope * profile.sigma * profile.sigma * u.slope.transpose(), 1e-2));
  }
}

TEST(TimeOffset, AFlatProfileHasNoSigma) {
  const auto flat = [](double) { return ProfilePoint{.cost = 5.0}; };
  const OffsetUncertainty u = ProfileUncertainty(flat, 0.0, flat(0.0), 1e-3);
  EXPECT_FALSE(u.curved);
  EXPECT_EQ(u.sigma, 0.0);
}

}  // namespace
}  // namespace hecal::streams
