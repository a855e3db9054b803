// `hecal plan` on the bundled example (data/plan-example: a camera on an arm's flange, the
// kuka2 chessboard on the table): every planned pose is checked independently — inside the
// workspace, and the whole board projected inside the image at the nominal — and the mistakes
// are refused with exit 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli_test_util.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/target_file.h"

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;
using cli_test::kData;
using ::testing::HasSubstr;

class PlanTest : public CliTest {
 protected:
  std::vector<std::string> Plan(const std::string& workspace) {
    return {"plan",
            "--setup",
            "eye-in-hand",
            "--target",
            kData + "rwhe-kuka2/target.yaml",
            "--intrinsics",
            kData + "plan-example/camera.yaml",
            "--workspace",
            workspace,
            "--output",
            Path("plan.csv")};
  }
};

TEST_F(PlanTest, EveryPlannedPoseSeesTheBoardInsideTheWorkspace) {
  std::vector<std::string> args = Plan(kData + "plan-example/workspace.yaml");
  for (const char* extra : {"--stations", "8", "--units", "mm", "--goal", "0.05deg,0.5mm"})
    args.push_back(extra);
  const cli_test::Outcome run = Hecal(args);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("predicted 1σ of X with the plan (8 stations)"));
  EXPECT_THAT(run.out, HasSubstr("goal 0.05 deg, 0.5 mm per axis: reached with"));
  const io::PoseTable plan = io::ReadPoseTable(Path("plan.csv"), {});
  ASSERT_EQ(plan.rows.size(), 8u);
  EXPECT_EQ(plan.unit, io::LengthUnit::kMillimetre);
  const io::Workspace workspace = io::ReadWorkspaceFile(kData + "plan-example/workspace.yaml");
  const pose::CameraModel camera = io::ReadCameraFile(kData + "plan-example/camera.yaml").camera;
  const std::vector<pose::ObjectPoint> board =
      pose::ObjectPoints(io::ReadTargetFile(kData + "rwhe-kuka2/target.yaml"));
  for (const io::PoseRow& row : plan.rows) {
    EXPECT_TRUE(workspace.Contains(row.pose)) << *row.id;
    const Pose T_camera_target = (row.pose * *workspace.hand_eye).inverse() * *workspace.target;
    for (const pose::ObjectPoint& point : board) {
      const Eigen::Vector3d p = T_camera_target * point.position;
      ASSERT_GT(p.z(), 0.0);
      const Eigen::Vector2d pixel = pose::Project(camera, p);
      EXPECT_GT(pixel.x(), 0.0);
      EXPECT_LT(pixel.x(), camera.width);
      EXPECT_GT(pixel.y(), 0.0);
      EXPECT_LT(pixel.y(), camera.height);
    }
  }
}

TEST_F(PlanTest, NextPosesLowerTheExistingCovariance) {
  // An existing calibration of 5 stations, the camera poses from the nominal scene.
  std::vector<std::string> args = Plan(kData + "plan-example/workspace.yaml");
  args.insert(args.end(), {"--stations", "5", "--seed", "7"});
  ASSERT_EQ(Hecal(args).code, 0);
  const io::PoseTable robot = io::ReadPoseTable(Path("plan.csv"), {});
  const io::Workspace workspace = io::ReadWorkspaceFile(kData + "plan-example/workspace.yaml");
  io::PoseTable camera;
  for (const io::PoseRow& row : robot.rows) {
    io::PoseRow view = row;
    view.pose = (row.pose * *workspace.hand_eye).inverse() * *workspace.target;
    camera.rows.push_back(view);
  }
  io::WritePoseTable(Path("robot.csv"), robot, {});
  io::WritePoseTable(Path("camera.csv"), camera, {});
  std::vector<std::string> next = Plan(kData + "plan-example/workspace.yaml");
  next.insert(next.end(), {"--existing", Path("robot.csv"), Path("camera.csv"), "--next", "3",
                           "--robot-sigma", "0.1,0.05", "--camera-sigma", "0.5,0.1"});
  const cli_test::Outcome run = Hecal(next);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("predicted 1σ of X now (5 stations)"));
  EXPECT_THAT(run.out, HasSubstr("with the plan (8 stations)"));
  EXPECT_THAT(run.out, HasSubstr("nominal X and Z: the existing calibration"));
  EXPECT_EQ(io::ReadPoseTable(Path("plan.csv"), {}).rows.size(), 3u);
}

TEST_F(PlanTest, MistakesAreRefused) {
  const auto refused = [&](std::vector<std::string> args, const std::string& words) {
    const cli_test::Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << run.out;
    EXPECT_THAT(run.err, HasSubstr(words));
  };
  const std::string far = Write("far.yaml",
                                "position_min: [0.2, -0.5, 0.2]\nposition_max: [1.0, 0.5, 1.0]\n"
                                "hand_eye: [0, 0, 0.08, 1, 0, 0, 0]\n"
                                "target: [5, 0, 0, 0, 1, 0, 0]\n");
  refused(Plan(far), "keep the whole target in view");
  const std::string bare = Write("bare.yaml", "position_min: [0, 0, 0]\nposition_max: [1, 1, 1]\n");
  refused(Plan(bare), "no nominal hand_eye");
  std::vector<std::string> next = Plan(kData + "plan-example/workspace.yaml");
  next.insert(next.end(), {"--existing", "a.csv", "b.csv"});
  refused(next, "--next");
  std::vector<std::string> goal = Plan(kData + "plan-example/workspace.yaml");
  goal.insert(goal.end(), {"--goal", "0.05,0.5"});
  refused(goal, "--goal");
  EXPECT_FALSE(std::filesystem::exists(Path("plan.csv")));
}

}  // namespace
}  // namespace hecal::cli
