// The contour study text against lines written by hand for one step whose numbers are known:
// Tx's Monte Carlo error 0.5 ± 2 mm against the UT's −0.25 ± 2.2 mm (ratio 1.1, flagged), every
// other component 0 ± 1 (1 rad shows as 57.2958°), three failed samples, and a Monte Carlo
// correlation of 0.5 between Tx and Rx (shown) and −0.2 between Ty and Tz (below 0.3: not shown).
#include "hecal/report/contour_study_text.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace hecal::report {
namespace {

// Filled in place: the step's other vectors stay unset and are not printed.
void Fill(contour::StudyStep& step) {
  step.value = 10.0;
  step.mc_mean_error << 0.5, 0, 0, 0, 0, 0;
  step.mc_sd << 2.0, 1, 1, 1, 1, 1;
  step.ut_mean_error << -0.25, 0, 0, 0, 0, 0;
  step.ut_sd << 2.2, 1, 1, 1, 1, 1;
  step.mc_covariance = Matrix6d::Identity();
  step.mc_covariance(0, 3) = step.mc_covariance(3, 0) = 0.5;
  step.mc_covariance(1, 2) = step.mc_covariance(2, 1) = -0.2;
  step.bias = {true, false, false, false, false, false};
  step.mc_failures = 3;
}

TEST(ContourStudyText, Lines) {
  contour::ContourStudyOptions options;
  options.motion = contour::StudyMotion::kTx;
  options.target = Eigen::Matrix2Xd::Zero(2, 12);
  std::vector<contour::StudyStep> steps(1);
  Fill(steps[0]);
  std::ostringstream out;
  PrintContourStudy(out, options, steps);
  EXPECT_EQ(out.str(),
            "contour study: motion tx, Z0 5000 mm, f 50 mm (6024.1 px), σ 0.5 px, 12 control "
            "points, Monte Carlo 5000 samples (seed 1), UT 13 points\n"
            "errors against the true motion: mean ± sd (mm, deg); ratio = UT sd / MC sd; * = bias "
            "flag (docs/contour.md#the-bias-check)\n"
            "tx (mm) = 10.00\n"
            "  Tx  MC    0.5000 ±   2.0000   UT   -0.2500 ±   2.2000   ratio 1.100 *\n"
            "  Ty  MC    0.0000 ±   1.0000   UT    0.0000 ±   1.0000   ratio 1.000\n"
            "  Tz  MC    0.0000 ±   1.0000   UT    0.0000 ±   1.0000   ratio 1.000\n"
            "  Rx  MC    0.0000 ±  57.2958   UT    0.0000 ±  57.2958   ratio 1.000\n"
            "  Ry  MC    0.0000 ±  57.2958   UT    0.0000 ±  57.2958   ratio 1.000\n"
            "  Rz  MC    0.0000 ±  57.2958   UT    0.0000 ±  57.2958   ratio 1.000\n"
            "  (3 Monte Carlo samples failed)\n"
            "largest |correlation| over the steps (Monte Carlo): Tx–Rx 0.50 (pairs below 0.3 not "
            "shown)\n");
}

}  // namespace
}  // namespace hecal::report
