// The branch-and-bound on noise-free scenes: exact recovery and a certificate closed to ε, in
// both setups. (Global optimality against a dense search: branch_and_bound_slow_test.cc.)
#include "hecal/global/branch_and_bound.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hecal/core/error.h"
#include "testing/epipolar_scenes.h"

namespace hecal::global {
namespace {

TEST(SolveGlobal, RecoversXFromNoiseFreeScenesWithAClosedCertificate) {
  for (const auto setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    testing::EpipolarSceneSpec spec;
    spec.motions = 5;
    spec.pairs = 20;
    spec.setup = setup;
    const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 21);
    SearchOptions options;
    options.epsilon = 1e-6;
    options.translation_bound = 1.0;
    const GlobalSolution solution = SolveGlobal(scene.problem, options);
    const Certificate& c = solution.certificate;
    EXPECT_TRUE(c.certified);
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
  EXPECT_NE(bad([](SearchOptions& o) { o.threads = -1; }).find("threads"), std::string::npos);
  EXPECT_EQ(bad([](SearchOptions& o) { o.threads = 257; }).rfind("SearchOptions.threads: ", 0), 0u);
  SearchOptions invalid;
  invalid.max_cubes = 0;
  EXPECT_THROW(SolveGlobal(EpipolarProblem{}, invalid), InputError);
}

}  // namespace
}  // namespace hecal::global
