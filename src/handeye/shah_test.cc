#include "hecal/handeye/shah.h"

#include <gtest/gtest.h>

#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

TEST(Shah, NoCatastrophicTrialWithNoise) {
  const testing::NoisyStudy study = testing::RunNoisyStudy(SolveShah, 200, 7000);
  EXPECT_LT(study.worst_rotation_deg, 10.0);
  EXPECT_LT(study.worst_z_rotation_deg, 10.0);
}

TEST(Shah, DegenerateDataThrow) {
  testing::ExpectDegenerateDataThrow(SolveShah);
}

TEST(Shah, TabbDatasetWithinUpstreamTolerance) {
  testing::ExpectWithinTabbTolerance(SolveShah, "shah");
}

}  // namespace
}  // namespace hecal::handeye
