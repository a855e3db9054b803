// How much a single plane weakens the target-free estimate (docs/global.md, "Planar scenes"):
// the same motions and noise with the scene points on one plane (fronto-parallel in the first
// camera, 1 m away) and spread in depth (0.6–1.4 m), through the pipeline of `hecal calibrate
// --method global` (pre-filter, local start, L∞ search, re-check and polish). Prints, per
// scene kind, the mean rotation and translation error of the polished X, the mean 1σ of the
// polish's covariance, the mean NEES and how many correct matches were removed. Asserts that
// both kinds recover X within their covariance (mean NEES in a wide band) and that the planar
// scenes' σ is not smaller than the 3-D scenes'. Slow: HECAL_PLANAR_TRIALS scenes per kind
// (default 20), several seconds each.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "hecal/estimation/epipolar_polish.h"
#include "hecal/geometry/se3.h"
#include "hecal/global/outlier_removal.h"
#include "testing/epipolar_scenes.h"

namespace hecal::global {
namespace {

struct Summary {
  double rotation_error = 0.0, translation_error = 0.0;  // radians, metres (means)
  double rotation_sigma = 0.0, translation_sigma = 0.0;  // RMS over axes, means
  double nees = 0.0;
  long removed = 0;
};

Summary RunScenes(bool planar, int trials) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 3;
  spec.pairs = 40;
  spec.pixel_sigma = 0.5;
  spec.planar = planar;
  OutlierOptions options;
  options.threshold = 4.0 * std::sqrt(2.0) * spec.pixel_sigma / spec.focal;
  SearchOptions search;
  search.epsilon = options.threshold;
  search.translation_bound = 1.0;
  Summary s;
  for (int trial = 0; trial < trials; ++trial) {
    const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 7000 + trial);
    const RobustGlobalSolution robust = SolveGlobalRobust(scene.problem, search, options);
    const estimation::RecheckedPolish rechecked =
        estimation::PolishAndRecheck(scene.problem, robust.inliers, robust.solution.X);
    const estimation::EpipolarPolish& polish = rechecked.polish;
    const Vector6d error = se3::Log(polish.X.inverse() * scene.X);
    s.rotation_error += testing::RotationError(polish.X, scene.X) / trials;
    s.translation_error += (polish.X.translation() - scene.X.translation()).norm() / trials;
    s.rotation_sigma += std::sqrt(polish.covariance.diagonal().head<3>().mean()) / trials;
    s.translation_sigma += std::sqrt(polish.covariance.diagonal().tail<3>().mean()) / trials;
    s.nees += error.dot(polish.covariance.inverse() * error) / trials;
    s.removed += long(rechecked.removed.size());
  }
  std::printf(
      "%s, %d scenes: X error %.4f deg / %.2f mm, 1 sigma %.4f deg / %.2f mm, mean NEES %.2f, "
      "%ld correct matches removed\n",
      planar ? "planar" : "3-D   ", trials, s.rotation_error * 180.0 / M_PI,
      1e3 * s.translation_error, s.rotation_sigma * 180.0 / M_PI, 1e3 * s.translation_sigma, s.nees,
      s.removed);
  return s;
}

TEST(PlanarScenes, WeakenTheEstimateAgainstScenesSpreadInDepth) {
  const char* env = std::getenv("HECAL_PLANAR_TRIALS");
  const int trials = env ? std::max(1, std::atoi(env)) : 20;
  const Summary spread = RunScenes(false, trials);
  const Summary planar = RunScenes(true, trials);
  for (const Summary* s : {&spread, &planar}) {
    EXPECT_NEAR(s->nees, 6.0, std::max(2.0, 6.0 * std::sqrt(12.0 / trials)));
  }
  EXPECT_GE(planar.rotation_sigma, spread.rotation_sigma);
  EXPECT_GE(planar.translation_sigma, spread.translation_sigma);
}

}  // namespace
}  // namespace hecal::global
