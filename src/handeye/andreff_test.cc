#include "hecal/handeye/andreff.h"

#include <gtest/gtest.h>

#include "hecal/core/error.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

testing::ProblemSolver Andreff() {
  return testing::FromMotionSolver([](const auto& motions) { return SolveAndreff(motions); });
}

TEST(Andreff, NoCatastrophicTrialWithNoise) {
  EXPECT_LT(testing::RunNoisyStudy(Andreff(), 200, 6000).worst_rotation_deg, 10.0);
}

TEST(Andreff, DegenerateDataThrow) {
  testing::ExpectDegenerateDataThrow(Andreff());
  EXPECT_THROW(SolveAndreff({}), DegenerateError);
}

}  // namespace
}  // namespace hecal::handeye
