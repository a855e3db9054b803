#include "hecal/report/contour_study_file.h"

#include <gtest/gtest.h>

#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace hecal::report {
namespace {

std::vector<contour::StudyStep> TwoSteps() {
  std::vector<contour::StudyStep> steps(2);
  for (int k = 0; k < 2; ++k) {
    contour::StudyStep& s = steps[static_cast<std::size_t>(k)];
    s.value = 10.0 * k;
    s.truth.setZero();
    s.mc_mean_error.setConstant(0.01);
    s.mc_sd.setConstant(0.1);
    s.ut_mean_error.setConstant(0.02);
    s.ut_sd.setConstant(0.2);
    s.mc_covariance = s.ut_covariance = Matrix6d::Identity() * 0.01;
    s.bias.fill(false);
  }
  steps[1].bias[3] = true;
  return steps;
}

// The CSV of docs/contour.md: a comment, the header, six rows per step; rotations in degrees.
TEST(ContourStudyCsv, OneRowPerStepAndComponentInDisplayUnits) {
  contour::ContourStudyOptions options;
  options.motion = contour::StudyMotion::kRx;
  options.seed = 9;
  options.samples = 300;
  const std::string csv = ContourStudyCsv(options, TwoSteps());
  std::istringstream lines(csv);
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(lines, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 2u + 12u);
  EXPECT_EQ(rows[0], "# hecal contour study: seed 9, 300 Monte Carlo samples per step");
  EXPECT_EQ(rows[1], "motion,value,component,mc_mean_error,mc_std,ut_mean_error,ut_std,bias");
  EXPECT_EQ(rows[2], "rx,0,Tx,0.01,0.1,0.02,0.2,0");  // translations stay in mm
  std::ostringstream rx;
  rx.precision(10);
  rx << "rx,10,Rx," << 0.01 * 180.0 / std::numbers::pi << ',' << 0.1 * 180.0 / std::numbers::pi;
  EXPECT_EQ(rows[2 + 6 + 3].rfind(rx.str(), 0), 0u) << rows[11];
  EXPECT_EQ(rows[2 + 6 + 3].back(), '1');  // the bias flag of Rx at step 2
}

TEST(NearestStep, PicksTheClosestMotionValueAndTheFirstOfEquals) {
  const std::vector<contour::StudyStep> steps = TwoSteps();
  EXPECT_EQ(NearestStep(steps, 7.0).value, 10.0);
  EXPECT_EQ(NearestStep(steps, 5.0).value, 0.0);
  EXPECT_EQ(NearestStep(steps, -3.0).value, 0.0);
}

// The page data: every step in display units, Fig. 4's step the nearest to `at` with its
// covariances scaled per component (mm², mm·deg, deg²) and its poses as errors against the truth.
TEST(ContourStudyPage, StepsAndTheCovarianceStepInDisplayUnits) {
  contour::ContourStudyOptions options;
  options.motion = contour::StudyMotion::kRx;
  std::vector<contour::StudyStep> steps = TwoSteps();
  steps[1].truth << 0, 0, 5000, 0.2, 0, 0;
  steps[1].mc_poses = {steps[1].truth, steps[1].truth};
  steps[1].mc_poses[1](0) += 1.0;   // 1 mm along Tx
  steps[1].mc_poses[1](3) += 0.01;  // 0.01 rad about x
  steps[1].sigma_poses.assign(13, steps[1].truth);
  const nlohmann::json data = ContourStudyPageData(options, steps, 8.0, "rx.html");
  EXPECT_EQ(data["kind"], "contour_study");
  EXPECT_EQ(data["title"], "rx.html");
  EXPECT_EQ(data["motion"], "rx");
  EXPECT_EQ(data["motion_label"], "rx (deg)");
  EXPECT_EQ(data["components"].size(), 6u);
  EXPECT_EQ(data["units"][0], "mm");
  EXPECT_EQ(data["units"][3], "deg");
  ASSERT_EQ(data["steps"].size(), 2u);
  const double deg = 180.0 / std::numbers::pi;
  EXPECT_DOUBLE_EQ(data["steps"][0]["mc_sd"][0].get<double>(), 0.1);  // mm stay mm
  EXPECT_DOUBLE_EQ(data["steps"][0]["ut_sd"][4].get<double>(), 0.2 * deg);
  EXPECT_TRUE(data["steps"][1]["bias"][3].get<bool>());
  const nlohmann::json& cov = data["covariance"];
  EXPECT_EQ(cov["value"], 10.0);  // 8 is nearer to 10 than to 0
  EXPECT_DOUBLE_EQ(cov["mc_covariance"][0][0].get<double>(), 0.01);
  EXPECT_DOUBLE_EQ(cov["mc_covariance"][0][3].get<double>(), 0.0);
  EXPECT_NEAR(cov["ut_covariance"][3][3].get<double>(), 0.01 * deg * deg, 1e-9);
  ASSERT_EQ(cov["mc_samples"].size(), 2u);
  EXPECT_NEAR(cov["mc_samples"][1][0].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(cov["mc_samples"][1][3].get<double>(), 0.01 * deg, 1e-6);
  EXPECT_NEAR(cov["mc_samples"][0][5].get<double>(), 0.0, 1e-12);
  EXPECT_EQ(cov["sigma_points"].size(), 13u);
}

}  // namespace
}  // namespace hecal::report
