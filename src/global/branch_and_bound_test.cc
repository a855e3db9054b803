// The branch-and-bound on noise-free scenes: exact recovery and a certificate closed to ε, in
// both setups. (Global optimality against a dense search: branch_and_bound_slow_test.cc.)
#include "hecal/global/branch_and_bound.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "testing/epipolar_scenes.h"

namespace hecal::global {
namespace {

// The noise-free scene of these tests (5 motions of 20 ray pairs, seed 21) and search options
// that close the certificate to 1e-6 rad on it.
testing::EpipolarScene FiveMotionScene(handeye::Setup setup = handeye::Setup::kEyeInHand) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 5;
  spec.pairs = 20;
  spec.setup = setup;
  return testing::MakeEpipolarScene(spec, 21);
}

SearchOptions TightOptions() {
  SearchOptions options;
  options.epsilon = 1e-6;
  options.translation_bound = 1.0;
  return options;
}

TEST(SolveGlobal, RecoversXFromNoiseFreeScenesWithAClosedCertificate) {
  for (const auto setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::EpipolarScene scene = FiveMotionScene(setup);
    const SearchOptions options = TightOptions();
    const GlobalSolution solution = SolveGlobal(scene.problem, options);
    const Certificate& c = solution.certificate;
    EXPECT_TRUE(c.certified);
    EXPECT_EQ(c.stopped_by, StopReason::kGapReached);
    EXPECT_GE(c.lower, 0.0);
    EXPECT_LE(c.upper - c.lower, options.epsilon);
    EXPECT_LE(c.upper, options.epsilon);  // the truth has error 0
    EXPECT_GT(c.cubes, 0);
    EXPECT_GE(c.lps, c.cubes / 8);
    // An error of 1e-6 rad bounds X to a few times that on this geometry (the L2 polish,
    // estimation/epipolar_polish.h, takes it to the truth).
    EXPECT_LT(testing::RotationError(solution.X, scene.X), 2e-5);
    EXPECT_LT((solution.X.translation() - scene.X.translation()).norm(), 2e-5);
  }
}

// A clock that moves one second per reading: the budget runs out after a known number of checks,
// whatever the machine's load.
struct SteppingClock {
  double now = 0.0;
  double operator()() { return now += 1.0; }
};

// Asserts what every stopped search must hand back: bounds in order, `upper` the max E of X.
void ExpectValidUncertified(const EpipolarProblem& problem, const GlobalSolution& solution) {
  const Certificate& c = solution.certificate;
  EXPECT_FALSE(c.certified);
  EXPECT_GE(c.lower, 0.0);
  EXPECT_LE(c.lower, c.upper);
  EXPECT_TRUE(std::isfinite(c.upper));
  EXPECT_NEAR(c.upper, MaxRayError(problem, solution.X), 1e-12);
}

TEST(SolveGlobal, StopsWhenTheTimeBudgetRunsOutWithTheBoundsProved) {
  const testing::EpipolarScene scene = FiveMotionScene();
  SearchOptions options = TightOptions();
  auto clock = std::make_shared<SteppingClock>();
  options.clock = [clock] { return (*clock)(); };
  options.time_budget = 4.0;  // the start and three checks: three batches of cubes at most
  std::vector<SearchProgress> reports;
  options.progress = [&reports](const SearchProgress& p) { reports.push_back(p); };
  options.progress_interval = 1.0;  // every check
  options.round = 7;
  const GlobalSolution solution = SolveGlobal(scene.problem, options);
  const Certificate& c = solution.certificate;
  ExpectValidUncertified(scene.problem, solution);
  EXPECT_EQ(c.stopped_by, StopReason::kTimeBudget);
  EXPECT_EQ(StopReasonName(c.stopped_by), "time budget");
  EXPECT_GT(c.cubes, 0);
  EXPECT_LE(c.cubes, 3 * 128);
  EXPECT_GE(c.seconds, options.time_budget);
  ASSERT_FALSE(reports.empty());
  for (std::size_t i = 0; i < reports.size(); ++i) {
    EXPECT_LE(reports[i].lower, reports[i].upper);
    EXPECT_EQ(reports[i].round, 7);
    if (i > 0) {  // the bounds only close
      EXPECT_GE(reports[i].lower, reports[i - 1].lower);
      EXPECT_LE(reports[i].upper, reports[i - 1].upper);
      EXPECT_GE(reports[i].cubes, reports[i - 1].cubes);
    }
  }
  EXPECT_GE(reports.back().upper, c.upper);
}

TEST(SolveGlobal, StopsWhenTheCubeBudgetRunsOut) {
  const testing::EpipolarScene scene = FiveMotionScene();
  SearchOptions options = TightOptions();
  options.max_cubes = 200;
  const GlobalSolution solution = SolveGlobal(scene.problem, options);
  ExpectValidUncertified(scene.problem, solution);
  EXPECT_EQ(solution.certificate.stopped_by, StopReason::kMaxCubes);
  EXPECT_EQ(StopReasonName(solution.certificate.stopped_by), "max cubes");
  EXPECT_GE(solution.certificate.cubes, options.max_cubes);
  EXPECT_LT(solution.certificate.cubes, options.max_cubes + 128);
}

TEST(SearchOptions, IsValidNamesTheBadField) {
  EXPECT_TRUE(SearchOptions{}.IsValid(nullptr));
  const auto bad = [](auto change) {
    SearchOptions options;
    change(options);
    std::string why;
    EXPECT_FALSE(options.IsValid(&why));
    return why;
  };
  EXPECT_NE(bad([](SearchOptions& o) { o.epsilon = 0.0; }).find("epsilon"), std::string::npos);
  EXPECT_NE(bad([](SearchOptions& o) { o.epsilon = NAN; }).find("epsilon"), std::string::npos);
  EXPECT_NE(bad([](SearchOptions& o) { o.relative_gap = 1.0; }).find("relative_gap"),
            std::string::npos);
  EXPECT_NE(bad([](SearchOptions& o) { o.translation_bound = -1.0; }).find("translation_bound"),
            std::string::npos);
  EXPECT_NE(bad([](SearchOptions& o) { o.min_half_width = 0.0; }).find("min_half_width"),
            std::string::npos);
  EXPECT_NE(bad([](SearchOptions& o) { o.max_cubes = 0; }).find("max_cubes"), std::string::npos);
  EXPECT_NE(bad([](SearchOptions& o) { o.time_budget = 0.0; }).find("time_budget"),
            std::string::npos);
  EXPECT_NE(bad([](SearchOptions& o) { o.time_budget = NAN; }).find("time_budget"),
            std::string::npos);
  EXPECT_NE(bad([](SearchOptions& o) { o.progress_interval = 0.0; }).find("progress_interval"),
            std::string::npos);
  EXPECT_NE(bad([](SearchOptions& o) { o.threads = -1; }).find("threads"), std::string::npos);
  EXPECT_EQ(bad([](SearchOptions& o) { o.threads = 257; }).rfind("SearchOptions.threads: ", 0), 0u);
  SearchOptions invalid;
  invalid.max_cubes = 0;
  EXPECT_THROW(SolveGlobal(EpipolarProblem{}, invalid), InputError);
}

}  // namespace
}  // namespace hecal::global
