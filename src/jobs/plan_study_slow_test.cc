// The table of docs/plan.md#does-it-help: planned against random stations, N = 6, 10, 15, 200
// calibrations each, both setups (plan_study.h). Run with
//   cmake --build build --target slow_checks && ctest --test-dir build -R jobs_plan_study_slow -V
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "hecal/jobs/plan_study.h"

namespace hecal::jobs {
namespace {

TEST(PlanStudy, TheTable) {
  std::printf("| setup | N | random: predicted / achieved rot (deg), trans (mm) | planned: "
              "predicted / achieved | achieved ratio random/planned |\n");
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    for (int n : {6, 10, 15}) {
      PlanStudyOptions options;
      options.setup = setup;
      options.stations = n;
      const PlanStudyRow row = RunPlanStudy(options);
      const auto cell = [](const PlanStudyArm& a) {
        char text[160];
        std::snprintf(text, sizeof text, "%.4f / %.4f, %.3f / %.3f",
                      a.predicted_rotation * 57.29577951308232, a.achieved_rotation * 57.29577951308232,
                      a.predicted_translation * 1e3, a.achieved_translation * 1e3);
        return std::string(text);
      };
      std::printf("| %s | %d | %s | %s | %.2f, %.2f |\n",
                  std::string(handeye::SetupName(setup)).c_str(), n, cell(row.random).c_str(),
                  cell(row.planned).c_str(), row.random.achieved_rotation / row.planned.achieved_rotation,
                  row.random.achieved_translation / row.planned.achieved_translation);
      EXPECT_LT(row.planned.achieved_translation, row.random.achieved_translation);
    }
  }
}

// --next on a weak existing set: 4 random stations, then 3 more (random or planned).
TEST(PlanStudy, NextOnAWeakSet) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    PlanStudyOptions options;
    options.setup = setup;
    options.existing = 4;
    options.stations = 3;
    const PlanStudyRow row = RunPlanStudy(options);
    std::printf("| %s | 4 + 3 | random: %.4f deg, %.3f mm | planned: %.4f deg, %.3f mm |\n",
                std::string(handeye::SetupName(setup)).c_str(),
                row.random.achieved_rotation * 57.29577951308232, row.random.achieved_translation * 1e3,
                row.planned.achieved_rotation * 57.29577951308232,
                row.planned.achieved_translation * 1e3);
    EXPECT_LT(row.planned.achieved_translation, row.random.achieved_translation);
  }
}

}  // namespace
}  // namespace hecal::jobs
