// `hecal calibrate --method global --images DIR --target none` on all 28 rwhe-kuka2 images
// (data/rwhe-kuka2/SOURCE.md; 27 consecutive motions, 18 of them pure 10° turns of the hand) as
// a user runs it: no search flag, so the default --time-budget (120 s) bounds the search, which
// does not certify on these motions (docs/global.md, Limits). Asserted: the command returns
// (exit 0) with a consistent certificate, the reason it stopped, a `hecal: warning:` line when a
// budget stopped it, progress lines on standard error while a long search ran, a search that
// overran its budget by at most one batch of cubes, and X near SOURCE.md's reference X
// (OpenCV's Park–Martin on the chessboard; hecal's `ml` is within 0.3 mm of it): within 1° and
// 30 mm, the measured 0.5° / 19 mm with room for the matches' seeds (docs/global.md, Measured;
// the 19 mm are the board's scale, which only the reference uses). The per-axis distance in
// the result's σ is printed (docs/global.md records it), not asserted: it is 5 σ on one axis.
// Slow: SIFT on 28 images of 1920 × 1200 and the 120 s search: 6.5 min wall at load 13–16.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_test_util.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "testing/camera_yaml.h"
#include "testing/kuka2_views.h"
#endif

namespace hecal::cli {
namespace {

#if defined(HECAL_HAVE_OPENCV_PEERS)

using cli_test::CliTest;
using cli_test::Hecal;
using nlohmann::json;

TEST_F(CliTest, GlobalOnAllKuka2ImagesReturnsWithinTheDefaultTimeBudget) {
  const std::string data = std::string(HECAL_SOURCE_DIR) + "/data/rwhe-kuka2";
  Write("camera.yaml", testing::CameraYaml(vision::kuka2::Camera()));
  const cli_test::Outcome run =
      Hecal({"calibrate", "--method", "global", "--images", data + "/images", "--target", "none",
             "--intrinsics", Path("camera.yaml"), "--robot", data + "/RobotPosesVec.txt", "--setup",
             "eye-in-hand", "--output", Path("global.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  const json g = json::parse(Read("global.json"));
  const json& c = g["certificate"];
  const double lower = c["lower"].get<double>(), upper = c["upper"].get<double>();
  const std::string stopped_by = c["stopped_by"].get<std::string>();
  const double seconds = c["search_seconds"].get<double>();
  std::printf("certificate [%.4g, %.4g] rad, stopped by %s after %.1f s of %.0f s, %d matches\n",
              lower, upper, stopped_by.c_str(), seconds, c["time_budget_s"].get<double>(),
              g["matches"]["inliers"].get<int>());
  EXPECT_EQ(c["time_budget_s"].get<double>(), 120.0);
  EXPECT_LE(0.0, lower);
  EXPECT_LE(lower, upper);
  EXPECT_TRUE(stopped_by == "gap reached" || stopped_by == "below threshold" ||
              stopped_by == "time budget" || stopped_by == "max cubes")
      << stopped_by;
  EXPECT_EQ(c["certified"].get<bool>(), stopped_by == "gap reached");
  // Checked before every batch of 128 cubes (well under a second of CPU each, 28 s at most under
  // the heaviest load measured here).
  EXPECT_LE(seconds, 120.0 + 30.0);
  if (stopped_by == "time budget" || stopped_by == "max cubes") {
    EXPECT_NE(run.err.find("hecal: warning: the global search stopped at its"), std::string::npos)
        << run.err;
    ASSERT_GE(g["warnings"].size(), 1u);  // the search's first (the model check's may follow)
    EXPECT_EQ(g["warnings"][0].get<std::string>().rfind("the global search stopped at its", 0), 0u);
  }
  if (seconds > 10.0) {
    EXPECT_NE(run.err.find("hecal: global search: solve "), std::string::npos) << run.err;
  }

  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  Eigen::Matrix<double, 6, 6> covariance;
  for (int r = 0; r < 3; ++r) {
    t(r) = g["X"]["translation_m"][r].get<double>();
    for (int k = 0; k < 3; ++k) R(r, k) = g["X"]["rotation"][r][k].get<double>();
  }
  for (int r = 0; r < 6; ++r) {
    for (int k = 0; k < 6; ++k) covariance(r, k) = g["covariance"]["X"][r][k].get<double>();
  }
  const Pose reference = vision::kuka2::X();
  // The reference as a right perturbation (ω, v) of the global X.
  const Eigen::AngleAxisd omega(R.transpose() * reference.linear());
  Eigen::Matrix<double, 6, 1> difference;
  difference << omega.angle() * omega.axis(), R.transpose() * (reference.translation() - t);
  std::printf("X from the reference: %.3f deg, %.1f mm; per axis in sigma:",
              omega.angle() * 180 / M_PI, 1e3 * (reference.translation() - t).norm());
  for (int k = 0; k < 6; ++k) std::printf(" %.2f", difference(k) / std::sqrt(covariance(k, k)));
  std::printf("\n");
  const json& check = g["covariance"]["model_check"];
  std::printf("model check: %s\n", check.dump().c_str());
  EXPECT_LT(omega.angle(), M_PI / 180.0);
  EXPECT_LT((reference.translation() - t).norm(), 0.030);
}

#endif

}  // namespace
}  // namespace hecal::cli
