// The contour paper's experiments (docs/contour.md#the-experiments) reproduced: 5000-sample Monte
// Carlo against the true motion, the UT against the Monte Carlo. Bounds are the paper's findings
// with margin; each sweep takes well under a second.
#include "hecal/contour/contour_study.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"

namespace hecal::contour {
namespace {
enum { kTx, kTy, kTz, kRx, kRy, kRz };

std::vector<StudyStep> Sweep(StudyMotion motion, double from, double to, int steps) {
  ContourStudyOptions options;
  options.motion = motion;
  options.from = from;
  options.to = to;
  options.steps = steps;
  return RunContourStudy(options);
}

double Correlation(const Matrix6d& C, int a, int b) {
  return C(a, b) / std::sqrt(C(a, a) * C(b, b));
}

TEST(ContourStudy, LateralTranslationIsRecoveredToAFewTenthsOfAPercent) {
  for (StudyMotion motion : {StudyMotion::kTx, StudyMotion::kTy}) {
    const int j = motion == StudyMotion::kTx ? kTx : kTy;
    const std::vector<StudyStep> steps = Sweep(motion, 50, 250, 5);
    for (const StudyStep& step : steps) {
      EXPECT_LT(std::abs(step.mc_mean_error(j)), 0.0025 * step.value) << step.value;  // ≲ 0.2%
      EXPECT_LT(step.mc_sd(j), 0.006 * step.value) << step.value;                     // ≲ 0.6%
      EXPECT_NEAR(step.ut_sd(j) / step.mc_sd(j), 1.0, 0.10) << step.value;
    }
    // The error and its spread grow off-centre.
    EXPECT_GT(steps.back().mc_sd(j), 1.5 * steps.front().mc_sd(j));
    EXPECT_GT(std::abs(steps.back().mc_mean_error(j)), std::abs(steps.front().mc_mean_error(j)));
  }
}

TEST(ContourStudy, DepthIsWorseAndImprovesAsTheCameraApproaches) {
  const std::vector<StudyStep> steps = Sweep(StudyMotion::kTz, 0, -3500, 8);
  for (std::size_t i = 1; i < steps.size(); ++i) {
    EXPECT_LT(steps[i].mc_sd(kTz), steps[i - 1].mc_sd(kTz)) << steps[i].value;
  }
  EXPECT_LT(steps.back().mc_sd(kTz), steps.front().mc_sd(kTz) / 5);
  // Tz is underestimated near zero tilt (its correlation with the overestimated tilts).
  EXPECT_LT(steps.front().mc_mean_error(kTz), -2 * steps.front().mc_sd(kTz) / std::sqrt(5000.0));
  // Worse than the lateral translation, relative to the distance.
  EXPECT_GT(steps.front().mc_sd(kTz), 20 * steps.front().mc_sd(kTx));
}

TEST(ContourStudy, OutOfPlaneRotationsArePoorBelowTenDegreesWithTheSignBias) {
  for (StudyMotion motion : {StudyMotion::kRx, StudyMotion::kRy}) {
    const int j = motion == StudyMotion::kRx ? kRx : kRy;
    const std::vector<StudyStep> steps = Sweep(motion, 0, 40, 9);  // 0, 5, …, 40°
    const StudyStep& zero = steps.front();
    EXPECT_GT(zero.mc_mean_error(j),
              1.0 * kRadiansPerDegree);  // the sign restriction biases upwards
    EXPECT_GT(zero.mc_sd(j), 1.5 * kRadiansPerDegree);
    EXPECT_TRUE(zero.bias[static_cast<std::size_t>(j)]);
    for (const StudyStep& step : steps) {
      if (step.value < 10.0) continue;
      EXPECT_LT(std::abs(step.mc_mean_error(j)), 0.3 * kRadiansPerDegree) << step.value;
      EXPECT_LT(step.mc_sd(j), 1.0 * kRadiansPerDegree) << step.value;
      EXPECT_FALSE(step.bias[static_cast<std::size_t>(j)]) << step.value;
      // Away from zero tilt the UT matches the Monte Carlo on every component.
      for (int k = 0; k < 6; ++k) {
        EXPECT_NEAR(step.ut_sd(k) / step.mc_sd(k), 1.0, 0.10) << step.value << " " << k;
      }
    }
    EXPECT_LT(steps.back().mc_sd(j), steps[2].mc_sd(j) / 2);
  }
}

TEST(ContourStudy, InPlaneRotationIsNegligiblyInError) {
  for (const StudyStep& step : Sweep(StudyMotion::kRz, 0, 180, 5)) {
    EXPECT_LT(std::abs(step.mc_mean_error(kRz)), 0.02 * kRadiansPerDegree) << step.value;
    EXPECT_LT(step.mc_sd(kRz), 0.2 * kRadiansPerDegree) << step.value;
    EXPECT_NEAR(step.ut_sd(kRz) / step.mc_sd(kRz), 1.0, 0.10) << step.value;
  }
}

TEST(ContourStudy, CorrelationsOfTheSeed) {
  // Tilted 10° about x (the paper's Fig. 4b): Rx–Tz correlated, negatively; the lateral
  // translations and Rz with nothing. A rotation about x gives a small spurious Ty (Fig. 4c).
  const StudyStep tilted = Sweep(StudyMotion::kRx, 10, 10, 1).front();
  EXPECT_LT(Correlation(tilted.mc_covariance, kRx, kTz), -0.3);
  for (int a : {kTx, kTy}) {
    for (int b = 0; b < 6; ++b) {
      if (b == a) continue;
      EXPECT_LT(std::abs(Correlation(tilted.mc_covariance, a, b)), 0.15) << a << b;
    }
  }
  const StudyStep twenty = Sweep(StudyMotion::kRx, 20, 20, 1).front();
  EXPECT_LT(twenty.mc_mean_error(kTy), -5 * twenty.mc_sd(kTy) / std::sqrt(5000.0));
  EXPECT_LT(std::abs(twenty.mc_mean_error(kTy)), 0.5);  // mm: small
  // Tilted about y: Ry–Tz.
  const StudyStep about_y = Sweep(StudyMotion::kRy, 10, 10, 1).front();
  EXPECT_LT(Correlation(about_y.mc_covariance, kRy, kTz), -0.3);
}

// Each checked field: one bad value, named first in `why`.
TEST(ContourStudyOptions, EachCheckedFieldRejectsABadValue) {
  std::string why;
  EXPECT_TRUE(ContourStudyOptions().IsValid(&why)) << why;
  const auto expect = [](const std::function<void(ContourStudyOptions&)>& spoil,
                         const std::string& field, const std::string& problem) {
    ContourStudyOptions options;
    spoil(options);
    std::string text;
    EXPECT_FALSE(options.IsValid(&text)) << field;
    EXPECT_EQ(text.rfind("ContourStudyOptions." + field + ": ", 0), 0u) << text;
    EXPECT_NE(text.find(problem), std::string::npos) << text;
  };
  expect([](ContourStudyOptions& o) { o.focal_mm = 0.0; }, "focal_mm", "positive");
  expect([](ContourStudyOptions& o) { o.z0_mm = -1.0; }, "z0_mm", "positive");
  expect([](ContourStudyOptions& o) { o.pixel_size_mm = NAN; }, "pixel_size_mm", "positive");
  expect([](ContourStudyOptions& o) { o.pixel_noise = 101.0; }, "pixel_noise",
         "must be 0 to 100 px, got 101");
  expect([](ContourStudyOptions& o) { o.pixel_noise = -0.1; }, "pixel_noise", "0 to 100 px");
  expect([](ContourStudyOptions& o) { o.from = INFINITY; }, "from", "finite");
  expect([](ContourStudyOptions& o) { o.steps = 10001; }, "steps", "from 1 to 10000, got 10001");
  expect([](ContourStudyOptions& o) { o.steps = 1; }, "steps", "at least 2 steps for a range");
  expect([](ContourStudyOptions& o) { o.samples = 1; }, "samples", "from 2 to 1000000, got 1");
  expect(
      [](ContourStudyOptions& o) {
        o.steps = 10000;
        o.samples = 20000;
      },
      "samples", "more than 100000000 Monte Carlo solves");
  expect([](ContourStudyOptions& o) { o.threads = 257; }, "threads", "from 0 to 256, got 257");
  expect(
      [](ContourStudyOptions& o) {
        o.motion = StudyMotion::kRy;
        o.to = -90.0;
      },
      "to", "below 90°");
  expect(
      [](ContourStudyOptions& o) {
        o.motion = StudyMotion::kTz;
        o.to = -5000.0;
      },
      "to", "above −Z0");
  expect([](ContourStudyOptions& o) { o.target = Eigen::Matrix2Xd::Zero(2, 3); }, "target",
         "at least 4 control points");
  expect(
      [](ContourStudyOptions& o) {
        o.unscented.unscented = uncertainty::UnscentedParameters::Symmetric(1.5);
      },
      "unscented", "");
}

TEST(ContourStudy, BadOptionsAreRejected) {
  ContourStudyOptions options;
  options.motion = StudyMotion::kRx;
  options.to = 90.0;
  EXPECT_THROW(RunContourStudy(options), InputError);
  options.to = 20.0;
  options.steps = 0;
  EXPECT_THROW(RunContourStudy(options), InputError);
  options.steps = 3;
  options.target = Eigen::Matrix2Xd::Zero(2, 6);
  EXPECT_THROW(RunContourStudy(options), DegenerateError);
  EXPECT_EQ(ParseStudyMotion("tz"), StudyMotion::kTz);
  EXPECT_FALSE(ParseStudyMotion("yaw"));
}

}  // namespace
}  // namespace hecal::contour
