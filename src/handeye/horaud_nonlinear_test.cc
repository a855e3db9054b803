#include "hecal/handeye/horaud_nonlinear.h"

#include <gtest/gtest.h>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

testing::ProblemSolver HoraudNonlinear() {
  return testing::FromMotionSolver(
      [](const auto& motions) { return SolveHoraudNonlinear(motions); });
}

TEST(HoraudNonlinear, NoCatastrophicTrialWithNoise) {
  EXPECT_LT(testing::RunNoisyStudy(HoraudNonlinear(), 200, 9000).worst_rotation_deg, 10.0);
}

TEST(HoraudNonlinear, DegenerateDataThrow) {
  testing::ExpectDegenerateDataThrow(HoraudNonlinear());
  EXPECT_THROW(SolveHoraudNonlinear({}), DegenerateError);
}

// From a start 30° and 10 cm off, the refinement still reaches the exact solution.
TEST(HoraudNonlinear, RefinementConvergesFromAPoorStart) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::Scene data = testing::ThesisCase(setup, 8, 51);
    const Pose start =
        data.X * MakePose(so3::Exp(Eigen::Vector3d(0.3, -0.3, 0.25)), Eigen::Vector3d(0.1, 0, 0));
    const Pose X = RefineHoraudNonlinear(AllPairMotions(data.MeasuredProblem()), start);
    testing::ExpectPoseNear(X, data.X, 1e-9, "X");
  }
}

}  // namespace
}  // namespace hecal::handeye
