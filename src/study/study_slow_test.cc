// The figures of docs/thesis-study.md on the thesis protocol, as a slow test (label "slow"; a
// few seconds on 2 cores in Release, much longer under sanitizers). `hecal simulate` produces
// the same numbers for the tables of docs/accuracy.md.
#include <gtest/gtest.h>


#include "hecal/geometry/angle_units.h"
#include "hecal/study/study.h"

namespace hecal::study {
namespace {

std::vector<Setting> Sweep(const std::vector<int>& stations, double mm, double deg) {
  std::vector<Setting> settings;
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    for (int n : stations) {
      Setting s;
      s.setup = setup;
      s.stations = n;
      s.translation_sigma = mm * 1e-3;
      s.rotation_sigma = deg * kRadiansPerDegree;
      settings.push_back(s);
    }
  }
  return settings;
}

std::vector<estimation::Method> Every() {
  std::vector<estimation::Method> methods;
  for (const estimation::MethodInfo& info : estimation::AllMethods())
    methods.push_back(info.method);
  return methods;
}

TEST(ThesisStudy, NoiseFreeEverySolverRecoversXTo1e9) {
  StudyOptions options;
  options.settings = Sweep({3, 5, 10, 20}, 0.0, 0.0);
  options.methods = Every();
  options.trials = 100;
  const StudyResult result = RunStudy(options);
  for (const MethodSummary& s : result.summaries) {
    const std::string name(estimation::Info(s.method).name);
    EXPECT_EQ(s.failures, 0) << name;
    EXPECT_LT(s.rotation.max, 1e-9) << name;
    EXPECT_LT(s.translation.max, 1e-9) << name;
  }
}

TEST(ThesisStudy, MlReachesTheFirstOrderBoundAtFifteenStations) {
  StudyOptions options;
  options.settings = Sweep({15}, 1.0, 1.0);
  options.methods = {estimation::Method::kMl};
  options.trials = 200;
  const StudyResult result = RunStudy(options);
  for (const MethodSummary& s : result.summaries) {
    const Bound& bound = result.setting_bounds[s.setting];
    EXPECT_NEAR(s.rotation.rmse / bound.rotation, 1.0, 0.1);
    EXPECT_NEAR(s.translation.rmse / bound.translation, 1.0, 0.1);
    EXPECT_LT(s.worst_rotation_over_bound, 10.0);
    EXPECT_LT(s.worst_translation_over_bound, 10.0);
  }
}

TEST(ThesisStudy, NoCatastrophicClosedFormTrialAtLowNoise) {
  StudyOptions options;
  options.settings = Sweep({5, 10, 20}, 0.3, 0.3);
  for (const estimation::MethodInfo& info : estimation::AllMethods()) {
    if (info.closed_form) options.methods.push_back(info.method);
  }
  options.trials = 200;
  const StudyResult result = RunStudy(options);
  for (const MethodSummary& s : result.summaries) {
    EXPECT_EQ(s.failures, 0) << estimation::Info(s.method).name;
    EXPECT_LT(s.rotation.max, 10.0 * kRadiansPerDegree) << estimation::Info(s.method).name;
  }
}

// The covariance consistency check of docs/uncertainty.md on 200 thesis-protocol trials (n = 15, σ
// = 1 mm / 1° on both), ml with the UT through the solver, both setups (the linear covariance is
// checked in the unit test): mean NEES in the 95% χ² band, 1σ/2σ coverage within 5 points (sampling
// sd 3.3 / 1.5).
TEST(ThesisStudy, MlUnscentedCovarianceIsConsistent) {
  StudyOptions options;
  options.settings = Sweep({15}, 1.0, 1.0);
  options.methods = {estimation::Method::kMl};
  options.trials = 200;
  options.covariance.method = estimation::CovarianceMethod::kUnscented;
  const StudyResult result = RunStudy(options);
  for (const MethodSummary& s : result.summaries) {
    ASSERT_TRUE(s.consistency.has_value());
    const uncertainty::Consistency& c = *s.consistency;
    EXPECT_TRUE(c.band.Contains(c.mean_nees)) << c.mean_nees;
    EXPECT_NEAR(c.coverage_1sigma, 0.683, 0.05);
    EXPECT_NEAR(c.coverage_2sigma, 0.954, 0.05);
  }
}

}  // namespace
}  // namespace hecal::study
