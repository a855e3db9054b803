// How much a single plane weakens the target-free X on rendered images (docs/global.md,
// "Measured"; docs/global.md): `hecal calibrate --method global --images DIR --target none` —
// SIFT, ratio and mutual checks, RANSAC, the L∞ search (--max-cubes 20000), the re-check and the
// polish with the robot error marginalised — on eye-in-hand station sets (testing/
// textured_stations.h: 10 stations, 9 motions of 10–18° and 2–5 cm, exact robot poses, 800 × 600
// px at f = 800 px, blur 0.6 px, noise 1 grey level) looking at (a) one textured plane 0.6 m away
// and (b) the inside of a box corner of the same extent (three planes, depths 0.4–0.75 m).
// Prints per scene and per kind (means): the X error (rotation °, translation mm) against the
// truth, the reported 1σ (RMS over the axes), the NEES, the mean z² per axis, the matches kept
// and removed, how many searches were certified; then the ratios planar / box corner of the
// errors and of the σ. The scenes alternate between the kinds. Asserts that every run succeeds;
// the figures are the study's output (docs/global.md, "Measured"). Slow: HECAL_RENDERED_TRIALS
// scenes per kind (default 10), 30–80 s each.
#include <gtest/gtest.h>

#include "cli_test_util.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "testing/rendered_global_scene.h"
#endif

namespace hecal::cli {
namespace {

#if defined(HECAL_HAVE_OPENCV_PEERS)

struct Summary {
  const char* name = "";
  int scenes = 0;
  double rotation_error = 0.0, translation_error = 0.0;  // sums, radians and metres
  double rotation_sigma = 0.0, translation_sigma = 0.0;  // sums of the RMS σ
  double nees = 0.0;
  Vector6d z2 = Vector6d::Zero();
  double inliers = 0.0, removed = 0.0;
  int certified = 0;

  void Add(const testing::RenderedGlobalOutcome& o) {
    std::printf(
        "%s %2d: error %.4f deg / %.3f mm, 1 sigma %.4f deg / %.3f mm, NEES %6.2f, z (%.1f %.1f "
        "%.1f | %.1f %.1f %.1f), %d kept, %d removed%s\n",
        name, scenes, o.rotation_error * 180 / M_PI, 1e3 * o.translation_error,
        o.rotation_sigma * 180 / M_PI, 1e3 * o.translation_sigma, o.nees, o.z(0), o.z(1), o.z(2),
        o.z(3), o.z(4), o.z(5), o.inliers, o.removed, o.certified ? ", certified" : "");
    std::fflush(stdout);
    ++scenes;
    rotation_error += o.rotation_error;
    translation_error += o.translation_error;
    rotation_sigma += o.rotation_sigma;
    translation_sigma += o.translation_sigma;
    nees += o.nees;
    z2 += o.z.cwiseAbs2();
    inliers += o.inliers;
    removed += o.removed;
    certified += o.certified ? 1 : 0;
  }

  void Print() const {
    const double n = scenes;
    std::printf(
        "%s, %d scenes: X error %.4f deg / %.3f mm, 1 sigma %.4f deg / %.3f mm, mean NEES %.2f, "
        "mean z2 (%.2f %.2f %.2f | %.2f %.2f %.2f), %.1f matches kept, %.1f removed, %d "
        "certified\n",
        name, scenes, rotation_error / n * 180 / M_PI, 1e3 * translation_error / n,
        rotation_sigma / n * 180 / M_PI, 1e3 * translation_sigma / n, nees / n, z2(0) / n,
        z2(1) / n, z2(2) / n, z2(3) / n, z2(4) / n, z2(5) / n, inliers / n, removed / n, certified);
  }
};

class CalibrateGlobalRenderedStudy : public cli_test::CliTest {};

TEST_F(CalibrateGlobalRenderedStudy, OnePlaneAgainstABoxCorner) {
  const char* env = std::getenv("HECAL_RENDERED_TRIALS");
  const int trials = env ? std::max(1, std::atoi(env)) : 10;
  Summary plane{"plane "}, corner{"corner"};
  // Scenes alternate between the kinds, so that a run cut short still compares them.
  for (int trial = 0; trial < trials; ++trial) {
    for (Summary* s : {&plane, &corner}) {
      testing::TexturedStationSpec spec;
      spec.shape = s == &plane ? testing::SceneShape::kPlane : testing::SceneShape::kCorner;
      const testing::RenderedGlobalOutcome o = testing::CalibrateRenderedScene(
          spec, 100 + std::uint64_t(trial), dir_ / (std::string(s->name) + std::to_string(trial)),
          {"--max-cubes", "20000"}, cli_test::Hecal);
      EXPECT_EQ(o.code, 0) << o.err;
      if (o.code == 0) s->Add(o);
    }
  }
  plane.Print();
  corner.Print();
  std::printf(
      "plane / corner: error %.2f (rotation), %.2f (translation); sigma %.2f (rotation), %.2f "
      "(translation)\n",
      plane.rotation_error / corner.rotation_error,
      plane.translation_error / corner.translation_error,
      plane.rotation_sigma / corner.rotation_sigma,
      plane.translation_sigma / corner.translation_sigma);
  EXPECT_EQ(plane.scenes, trials);
  EXPECT_EQ(corner.scenes, trials);
}

#endif

}  // namespace
}  // namespace hecal::cli
