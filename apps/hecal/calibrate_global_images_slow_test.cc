// `hecal calibrate --method global --images DIR --target target.yaml` on rendered images
// (testing/rendered_scene.h): the chessboard's corners are used as anonymous matches between
// consecutive stations, its size and square never. A camera on the robot (eye-in-hand) sees the
// board from known views B = T_camera_target; the robot poses G follow from a known X and Z
// (Z = G X B). Checks X against that truth and the result file's matches. Slow: the search takes
// minutes on these corners (docs/global.md, "Limits"), beyond the default --time-budget on a
// loaded machine, so the test raises it; the refusals of this form are in
// calibrate_global_test.cc.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_test_util.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <Eigen/Geometry>
#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hecal/geometry/angle_units.h"
#include "testing/camera_yaml.h"
#include "testing/detection_errors.h"
#include "testing/render_once.h"
#include "testing/rendered_scene.h"
#endif

namespace hecal::cli {
namespace {

#if defined(HECAL_HAVE_OPENCV_PEERS)

using cli_test::CliTest;
using cli_test::Hecal;
using nlohmann::json;

constexpr int kViews = 6;

// X = T_gripper_camera and Z = T_base_target of the scene (metres).
Pose TrueX() {
  return MakePose(
      Eigen::AngleAxisd(75 * kRadiansPerDegree, Eigen::Vector3d(-0.3, 1.0, 0.4).normalized())
          .toRotationMatrix(),
      Eigen::Vector3d(-0.05, 0.02, 0.12));
}
Pose TrueZ() {
  return MakePose(
      Eigen::AngleAxisd(160 * kRadiansPerDegree, Eigen::Vector3d(0.9, 0.2, 0.1).normalized())
          .toRotationMatrix(),
      Eigen::Vector3d(0.7, -0.1, 0.1));
}

class CalibrateGlobalImages : public hecal::testing::RenderOnce<CalibrateGlobalImages, CliTest> {
 public:
  static constexpr const char* kRenderFolder = "calibrate_global_images_test";
  static void Render(const std::filesystem::path& dir) {
    hecal::testing::MakeRenderedScene({.views = hecal::testing::SpreadViews({.count = kViews}),
                                       .first_seed = 200,
                                       .folder = dir});
  }

 protected:
  // robot.csv: T_base_gripper of every view, in the images' order.
  std::string RobotFile() {
    std::ostringstream csv;
    csv << std::setprecision(17) << "x,y,z,qw,qx,qy,qz\n";
    for (const Pose& B : hecal::testing::SpreadViews({.count = kViews})) {
      const Pose G = TrueZ() * B.inverse() * TrueX().inverse();  // Z = G X B
      const Eigen::Quaterniond q(G.linear());
      csv << G.translation().x() << "," << G.translation().y() << "," << G.translation().z() << ","
          << q.w() << "," << q.x() << "," << q.y() << "," << q.z() << "\n";
    }
    return Write("robot.csv", csv.str());
  }

  std::vector<std::string> Args() {
    return {"calibrate",
            "--method",
            "global",
            "--images",
            RenderDir().string(),
            "--target",
            Write("target.yaml", hecal::testing::kBoardYaml),
            "--intrinsics",
            Write("camera.yaml", hecal::testing::CameraYaml(hecal::testing::RenderCamera())),
            "--robot",
            RobotFile(),
            "--setup",
            "eye-in-hand",
            "--matches-per-motion",
            "30",
            "--epsilon",
            "1e-3",
            "--time-budget",  // the certificate is asserted: no time limit short of it
            "3600",
            "--output",
            Path("result.json")};
  }
};

Pose PoseOf(const json& object) {
  Pose X = Pose::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) X.matrix()(r, c) = object["rotation"][r][c].get<double>();
    X.matrix()(r, 3) = object["translation_m"][r].get<double>();
  }
  return X;
}

// Sub-pixel corners of rendered images (≈0.03 px): X within 0.1° and 1 mm of the truth; the
// matches are the board's corners, 30 per motion. The certificate's gap is 1e-3 rad (≈0.6 px):
// a smaller one takes minutes on these noisy corners (docs/global.md, "Limits").
TEST_F(CalibrateGlobalImages, RecoversXFromTheTargetCornersAsAnonymousMatches) {
  const cli_test::Outcome run = Hecal(Args());
  ASSERT_EQ(run.code, 0) << run.err;
  const json result = json::parse(Read("result.json"));
  const Pose X = PoseOf(result["X"]);
  EXPECT_LT(hecal::testing::RotationErrorDeg(X, TrueX()), 0.1) << run.out;
  EXPECT_LT(hecal::testing::TranslationErrorMm(X, TrueX()), 1.0) << run.out;
  EXPECT_EQ(result["method"], "global");
  EXPECT_EQ(result["matches"]["inliers"].get<int>() + int(result["matches"]["removed"].size()),
            (kViews - 1) * 30);
  EXPECT_TRUE(result["certificate"]["certified"].get<bool>());
}

#endif

}  // namespace
}  // namespace hecal::cli
