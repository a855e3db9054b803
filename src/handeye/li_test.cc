#include "hecal/handeye/li.h"

#include <gtest/gtest.h>

#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

TEST(Li, NoCatastrophicTrialWithNoise) {
  const testing::NoisyStudy study = testing::RunNoisyStudy(SolveLi, 200, 8000);
  EXPECT_LT(study.worst_rotation_deg, 10.0);
  EXPECT_LT(study.worst_z_rotation_deg, 10.0);
}

TEST(Li, DegenerateDataThrow) {
  testing::ExpectDegenerateDataThrow(SolveLi);
}

TEST(Li, TabbDatasetWithinUpstreamTolerance) {
  testing::ExpectWithinTabbTolerance(SolveLi, "li");
}

// Translations are normalised before the joint system is formed, so the length unit does not
// change the (noisy) result beyond scaling it.
TEST(Li, ResultDoesNotDependOnTheLengthUnit) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeToHand, 10, 41, 0.01, 1e-3);
  Problem problem = data.MeasuredProblem();
  const Solution in_m = SolveLi(problem);
  for (Pose& A : problem.A) A.translation() *= 1000.0;
  for (Pose& B : problem.B) B.translation() *= 1000.0;
  const Solution in_mm = SolveLi(problem);
  EXPECT_LT(so3::Distance(in_m.X.linear(), in_mm.X.linear()), 1e-10);
  EXPECT_LT(so3::Distance(in_m.Z.linear(), in_mm.Z.linear()), 1e-10);
  EXPECT_LT((1000.0 * in_m.X.translation() - in_mm.X.translation()).norm(), 1e-7);
  EXPECT_LT((1000.0 * in_m.Z.translation() - in_mm.Z.translation()).norm(), 1e-7);
}

}  // namespace
}  // namespace hecal::handeye
