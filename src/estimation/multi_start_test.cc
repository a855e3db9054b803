// RunMultiStart (multi_start.h): the optimum with the lowest objective is kept, starts in a found
// basin are skipped, and a refinement that fails from every start is reported as degenerate data
// (DegenerateError, exit 2 at the CLI), not as an internal error.
#include "multi_start.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/geometry/se3.h"

namespace hecal::estimation::internal {
namespace {

handeye::Solution Turned(double angle) {
  Vector6d xi = Vector6d::Zero();
  xi(2) = angle;
  return {se3::Exp(xi), Pose::Identity()};
}

TEST(RunMultiStart, KeepsTheLowestOptimumAndSkipsAFoundBasin) {
  const std::vector<handeye::Solution> starts = {Turned(0.0), Turned(0.01), Turned(1.0)};
  const auto evaluate = [](const handeye::Solution& s) { return se3::Log(s.X).head<3>().norm(); };
  // Each start refines to itself; the far one has the lower objective.
  const auto refine = [](const handeye::Solution& s) {
    const double angle = se3::Log(s.X).head<3>().norm();
    return Optimum{s, angle > 0.5 ? -1.0 : angle};
  };
  const MultiStartResult result = RunMultiStart(starts, 1.0, evaluate, refine);
  EXPECT_EQ(result.starts_refined, 2);  // 0.01 rad lies in the basin of the first
  EXPECT_EQ(result.distinct_minima, 2);
  EXPECT_EQ(result.best.value, -1.0);
}

TEST(RunMultiStart, FailingFromEveryStartIsDegenerateData) {
  const std::vector<handeye::Solution> starts = {Turned(0.0), Turned(1.0)};
  const auto evaluate = [](const handeye::Solution&) { return 0.0; };
  const auto refine = [](const handeye::Solution& s) {
    return Optimum{s, std::numeric_limits<double>::quiet_NaN()};
  };
  EXPECT_THROW(RunMultiStart(starts, 1.0, evaluate, refine), DegenerateError);
}

}  // namespace
}  // namespace hecal::estimation::internal
