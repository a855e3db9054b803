// The planning study (plan_study.h) at a size the unit run affords: planned stations give a
// clearly lower X error than the thesis protocol's random ones, and the prediction holds.
// The 200-trial table of docs/plan.md is plan_study_slow_test.cc.
#include "hecal/jobs/plan_study.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace hecal::jobs {
namespace {

TEST(PlanStudy, PlannedStationsBeatRandomOnes) {
  PlanStudyOptions options;
  options.stations = 8;
  options.trials = 30;
  options.pool = 150;
  const PlanStudyRow row = RunPlanStudy(options);
  std::printf("random %.5f rad %.6f m, planned %.5f rad %.6f m\n", row.random.achieved_rotation,
              row.random.achieved_translation, row.planned.achieved_rotation,
              row.planned.achieved_translation);
  EXPECT_LT(row.planned.achieved_rotation, row.random.achieved_rotation);
  EXPECT_LT(row.planned.achieved_translation, 0.8 * row.random.achieved_translation);
  for (const PlanStudyArm& arm : {row.random, row.planned}) {
    EXPECT_NEAR(arm.achieved_rotation / arm.predicted_rotation, 1.0, 0.35);
    EXPECT_NEAR(arm.achieved_translation / arm.predicted_translation, 1.0, 0.35);
  }
}

}  // namespace
}  // namespace hecal::jobs
