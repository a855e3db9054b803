#include "hecal/plan/view_candidates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hecal/io/workspace_file.h"

namespace hecal::plan {
namespace {

pose::CameraModel Camera() {
  pose::CameraModel camera;
  camera.fx = camera.fy = 2400.0;
  camera.cx = 960.0;
  camera.cy = 600.0;
  camera.width = 1920;
  camera.height = 1200;
  return camera;
}

std::vector<pose::ObjectPoint> Board() {
  pose::TargetSpec spec;
  spec.type = pose::TargetType::kChessboard;
  spec.cols = 9;
  spec.rows = 6;
  spec.square = 0.03;
  return pose::ObjectPoints(spec);
}

io::Workspace Space() {
  return io::ParseWorkspaceYaml(
      "position_min: [0.2, -0.5, 0.2]\nposition_max: [1.0, 0.5, 1.1]\nmax_tilt_deg: 70\n"
      "hand_eye: [0, -0.06, 0.08, 1, 0, 0, 0]\ntarget: [0.45, -0.1, 0, 0, 1, 0, 0]\n",
      "workspace.yaml");
}

TEST(ViewCandidates, EveryCandidateSeesTheWholeBoardInsideTheWorkspace) {
  const io::Workspace workspace = Space();
  const Scene scene{handeye::Setup::kEyeInHand, *workspace.hand_eye, *workspace.target};
  std::mt19937_64 rng(1);
  ViewOptions options;
  options.candidates = 100;
  int samples = 0;
  const std::vector<ViewCandidate> candidates =
      ViewCandidates({scene}, Camera(), Board(), workspace, options, rng, &samples);
  ASSERT_EQ(candidates.size(), 100u);
  EXPECT_GT(samples, 100);
  const double distance = DefaultDistance(Camera(), Board());
  for (const ViewCandidate& candidate : candidates) {
    EXPECT_TRUE(workspace.Contains(candidate.T_base_gripper));
    // The camera pose follows from the robot pose and the nominal (Z = A X B).
    const Pose B = (candidate.T_base_gripper * scene.X).inverse() * scene.Z;
    EXPECT_LT((B.matrix() - candidate.T_camera_target.matrix()).norm(), 1e-9);
    EXPECT_TRUE(TargetInView(Camera(), Board(), B, 0.05 * 1920));
    // At the planned distance from the board's centre, and no steeper than 45° to its normal.
    const Eigen::Vector3d centre(0.5 * 8 * 0.03, 0.5 * 5 * 0.03, 0.0);  // of the 9 × 6 points
    const Eigen::Vector3d camera_in_target = B.inverse().translation() - centre;
    EXPECT_LE(camera_in_target.norm(), 1.2 * distance + 1e-9);
    EXPECT_GE(camera_in_target.norm(), 0.8 * distance - 1e-9);
    EXPECT_LE(-camera_in_target.z(), camera_in_target.norm());
    EXPECT_GE(-camera_in_target.z(), std::cos(0.7853981633974483) * camera_in_target.norm() - 1e-9);
    EXPECT_LT(camera_in_target.z(), 0.0);
  }
}

TEST(ViewCandidates, ABoardOutOfReachGivesNone) {
  io::Workspace workspace = Space();
  workspace.target = MakePose(workspace.target->linear(), Eigen::Vector3d(5.0, 0.0, 0.0));
  const Scene scene{handeye::Setup::kEyeInHand, *workspace.hand_eye, *workspace.target};
  std::mt19937_64 rng(2);
  ViewOptions options;
  options.max_samples = 2000;
  EXPECT_TRUE(ViewCandidates({scene}, Camera(), Board(), workspace, options, rng).empty());
}

}  // namespace
}  // namespace hecal::plan
