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

TEST(ContourStudyFigure, IsOneSvgWithSixPanels) {
  contour::ContourStudyOptions options;
  const std::string svg = ContourStudyFigure(options, TwoSteps());
  EXPECT_EQ(svg.rfind("<svg", 0) == 0 || svg.rfind("<?xml", 0) == 0, true);
  for (const char* name :
       {"Tx error", "Ty error", "Tz error", "Rx error", "Ry error", "Rz error"}) {
    EXPECT_NE(svg.find(name), std::string::npos) << name;
  }
}

}  // namespace
}  // namespace hecal::report
