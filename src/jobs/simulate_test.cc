#include "hecal/jobs/simulate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"

namespace hecal::jobs {
namespace {

// `why` of an invalid options struct names the field first (core/options_check.h).
void ExpectInvalid(const std::function<void(SimulateOptions&)>& spoil, const std::string& field,
                   const std::string& problem) {
  SimulateOptions options;
  spoil(options);
  std::string why;
  EXPECT_FALSE(options.IsValid(&why)) << field;
  EXPECT_EQ(why.rfind("SimulateOptions." + field + ": ", 0), 0u) << why;
  EXPECT_NE(why.find(problem), std::string::npos) << why;
  try {
    Simulate(options);
    ADD_FAILURE() << "Simulate accepted a bad " << field;
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "SimulateOptions." + field);
    EXPECT_EQ(std::string(e.what()), why);
  }
}

TEST(SimulateOptions, DefaultsAreValid) {
  std::string why;
  EXPECT_TRUE(SimulateOptions().IsValid(&why)) << why;
  EXPECT_EQ(SimulateOptions().methods.size(), estimation::AllMethods().size());
}

TEST(SimulateOptions, EachCheckedFieldRejectsABadValue) {
  ExpectInvalid([](SimulateOptions& o) { o.setups.clear(); }, "setups", "no value");
  ExpectInvalid([](SimulateOptions& o) { o.noise_on.clear(); }, "noise_on", "no value");
  ExpectInvalid([](SimulateOptions& o) { o.noise.clear(); }, "noise", "no value");
  ExpectInvalid([](SimulateOptions& o) { o.methods.clear(); }, "methods", "no method");
  ExpectInvalid(
      [](SimulateOptions& o) {
        o.stations = {5, 2};
      },
      "stations", "'2' is outside the range 3 to 100000");
  ExpectInvalid([](SimulateOptions& o) { o.stations = {100001}; }, "stations", "outside");
  ExpectInvalid([](SimulateOptions& o) { o.outliers = {-1}; }, "outliers",
                "'-1' is outside the range 0 to 100000");
  ExpectInvalid([](SimulateOptions& o) { o.sigmas = {{0.1, 181.0}}; }, "sigmas", "0 to 180 deg");
  ExpectInvalid([](SimulateOptions& o) { o.sigmas = {{-0.1, 0.0}}; }, "sigmas", "0 to 1000 mm");
  ExpectInvalid(
      [](SimulateOptions& o) {
        o.sigmas = {{std::numeric_limits<double>::quiet_NaN(), 0.0}};
      },
      "sigmas", "noise levels");
  ExpectInvalid([](SimulateOptions& o) { o.robot_scales = {0.0}; }, "robot_scales", "above 0");
  ExpectInvalid([](SimulateOptions& o) { o.robot_scales = {1001.0}; }, "robot_scales",
                "at most 1000");
  // 100 mm times 20 is 2000 mm of robot noise.
  ExpectInvalid(
      [](SimulateOptions& o) {
        o.sigmas = {{100.0, 1.0}};
        o.robot_scales = {20.0};
      },
      "robot_scales", "must stay within 1000 mm and 180 deg");
  ExpectInvalid([](SimulateOptions& o) { o.trials = 0; }, "trials", "from 1 to 100000, got 0");
  ExpectInvalid([](SimulateOptions& o) { o.threads = -1; }, "threads", "from 0 to 256, got -1");
  ExpectInvalid([](SimulateOptions& o) { o.threads = 257; }, "threads", "from 0 to 256");
  ExpectInvalid([](SimulateOptions& o) { o.covariance_samples = 1; }, "covariance_samples",
                "from 2 to 100000, got 1");
  // 5 station counts × 3 levels × 700 outlier counts = 10500 settings.
  ExpectInvalid([](SimulateOptions& o) { o.outliers = std::vector<int>(700, 0); }, "stations",
                "10500 settings, more than 10000");
  // 15 settings × 100000 trials × 1 method.
  ExpectInvalid(
      [](SimulateOptions& o) {
        o.methods = {estimation::Method::kAndreff};
        o.trials = 100000;
      },
      "trials", "1500000 trial rows, more than 1000000");
}

TEST(MakeStudyOptions, OneSettingPerCombinationInNestingOrderAndSiUnits) {
  SimulateOptions options;
  options.setups = {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand};
  options.stations = {4, 6};
  options.sigmas = {{0.3, 2.0}};
  options.outliers = {0, 1};
  options.robot_scales = {1.0, 5.0};
  options.covariance = std::nullopt;
  options.covariance_samples = 77;
  options.seed = 9;
  const study::StudyOptions study = MakeStudyOptions(options);
  ASSERT_EQ(study.settings.size(), 2u * 2u * 2u * 2u);
  // Outliers vary fastest, then stations, ..., robot scale slowest.
  EXPECT_EQ(study.settings[0].gross_outliers, 0);
  EXPECT_EQ(study.settings[1].gross_outliers, 1);
  EXPECT_EQ(study.settings[2].stations, 6);
  EXPECT_EQ(study.settings[4].setup, handeye::Setup::kEyeToHand);
  EXPECT_EQ(study.settings[7].robot_scale, 1.0);
  EXPECT_EQ(study.settings[8].robot_scale, 5.0);
  EXPECT_DOUBLE_EQ(study.settings[0].translation_sigma, 0.3e-3);                       // m
  EXPECT_DOUBLE_EQ(study.settings[0].rotation_sigma, 2.0 * std::numbers::pi / 180.0);  // rad
  EXPECT_FALSE(study.covariance.method.has_value());
  EXPECT_EQ(study.covariance.samples, 77);
  EXPECT_EQ(study.covariance.seed, 9u);
  EXPECT_EQ(study.seed, 9u);
}

TEST(Simulate, NoiseFreeDataGiveTheTruthToRounding) {
  SimulateOptions options;
  options.stations = {4};
  options.sigmas = {{0.0, 0.0}};
  options.methods = {estimation::Method::kParkMartin};
  options.trials = 3;
  options.threads = 1;
  const study::StudyResult result = Simulate(options);
  ASSERT_EQ(result.trials.size(), 3u);
  for (const study::TrialResult& trial : result.trials) {
    EXPECT_EQ(trial.status, study::TrialStatus::kOk);
    EXPECT_LT(trial.rotation_error, 1e-9);
    EXPECT_LT(trial.translation_error, 1e-9);
  }
}

TEST(OptionsError, SplitsTheMessageIntoFieldProblemAndFix) {
  std::string why;
  EXPECT_FALSE(Invalid(&why, "A.b", "is bad (really)", "give c"));
  EXPECT_EQ(why, "A.b: is bad (really) (fix: give c)");
  const InputError error = OptionsError(why);
  EXPECT_EQ(error.source(), "A.b");
  EXPECT_EQ(error.problem(), "is bad (really)");
  EXPECT_EQ(error.fix(), "give c");
  EXPECT_EQ(std::string(error.what()), why);
  EXPECT_FALSE(Invalid(&why, "A.b", "no fix", ""));
  EXPECT_EQ(OptionsError(why).problem(), "no fix");
  EXPECT_EQ(OptionsError(why).fix(), "");
}

}  // namespace
}  // namespace hecal::jobs
