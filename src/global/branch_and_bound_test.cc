// The branch-and-bound on noise-free scenes: exact recovery and a certificate closed to ε, in
// both setups. (Global optimality against a dense search: branch_and_bound_slow_test.cc.)
#include "hecal/global/branch_and_bound.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace hecal::global
