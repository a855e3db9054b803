// The study and benchmark tables against lines written by hand for results whose numbers are
// known (a 2° / 3 mm RMSE, a hecal solve twice as fast as the peer's).
#include "hecal/report/study_text.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "hecal/geometry/angle_units.h"

namespace hecal::report {
namespace {

bool Has(const std::string& text, const std::string& line) {
  return text.find(line + "\n") != std::string::npos;
}

TEST(StudyText, OneSettingOneMethod) {
  study::StudyResult result;
  study::Setting setting;
  setting.stations = 5;
  setting.translation_sigma = 1e-3;
  setting.rotation_sigma = 1.0 * kRadiansPerDegree;
  result.options.settings = {setting};
  result.options.trials = 10;
  result.setting_bounds = {{0.5 * kRadiansPerDegree, 0.25e-3}};
  study::MethodSummary m;
  m.method = estimation::Method::kTsaiLenz;
  m.trials = 10;
  m.failures = 1;
  m.outliers = 2;
  m.rotation = {9,
                1,
                1.0 * kRadiansPerDegree,
                2.0 * kRadiansPerDegree,
                0.5 * kRadiansPerDegree,
                3.0 * kRadiansPerDegree,
                4.0 * kRadiansPerDegree};
  m.translation = {9, 1, 2e-3, 3e-3, 1e-3, 4e-3, 5e-6};
  result.summaries = {m};
  std::ostringstream out;
  PrintStudyTable(out, result);
  const std::string text = out.str();
  EXPECT_TRUE(Has(text,
                  "eye-in-hand, 5 stations, gaussian noise on both, sigma 1 mm / 1 deg, "
                  "10 trials"))
      << text;
  EXPECT_TRUE(Has(text,
                  "  first-order bound (ml at the truth): rotation RMSE 0.5000 deg, "
                  "translation RMSE 0.2500 mm"))
      << text;
  // A maximum of 5e-6 m is 5e-3 mm: fixed point; the same in degrees would be scientific.
  EXPECT_TRUE(Has(text,
                  "  tsai-lenz             1    2      1.0000    2.0000    0.5000    3.0000"
                  "     4.0000      2.0000    3.0000    1.0000    4.0000     0.0050"))
      << text;
  EXPECT_EQ(text.find("consistency"), std::string::npos);  // no covariance predicted
  EXPECT_EQ(text.find("found"), std::string::npos);        // no outliers injected or rejected
}

TEST(StudyText, BenchAgainstThePeer) {
  study::BenchResult result;
  result.options.sigma = {0.1, 0.1};
  result.options.datasets = 3;
  result.options.seed = 7;
  study::BenchRow hecal;
  hecal.impl = "hecal";
  hecal.method = estimation::Method::kTsaiLenz;
  hecal.start = study::BenchStart::kNotApplicable;
  hecal.stations = 10;
  hecal.us_per_solve = 5.0;
  hecal.accuracy.rotation_error = 0.01 * kRadiansPerDegree;
  hecal.accuracy.translation_error = 2e-7;  // 2e-4 mm: scientific
  study::BenchRow peer = hecal;
  peer.impl = "opencv";
  peer.us_per_solve = 10.0;
  peer.accuracy.failures = 1;
  result.rows = {hecal, peer};
  std::ostringstream out;
  PrintBenchTable(out, result);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("hecal bench: thesis protocol, eye-in-hand, Gaussian noise 0.1 (mm/deg) on "
                       "robot and camera, 3 data sets per station count, seed 7; ",
                       0),
            0u)
      << text;
  EXPECT_TRUE(Has(text,
                  "tsai-lenz           10        5.00       10.00      2.0x     0.0100"
                  "   2.0e-04    0      0.0100    2.0e-04    1"))
      << text;
}

}  // namespace
}  // namespace hecal::report
