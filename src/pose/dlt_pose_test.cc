// The normalised DLT: exact on noise-free data on both paths (projective for a volume, homography
// for a plane on any plane in the target frame), close to the truth under noise, and the
// refusals (too few points, a line, a homography with three of four points collinear).
#include "hecal/pose/dlt_pose.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "pose/pose_test_util.h"
#include "testing/options_validity.h"
#include "testing/pose_scenes.h"

namespace hecal::pose {
namespace {

using testing::PointShape;
using testing::RandomScene;

void ExpectExact(const DltPoseResult& result, const testing::PointView& scene, DltPath path) {
  EXPECT_EQ(result.path, path);
  EXPECT_LT(RotationError(result.T_camera_target, scene.T_camera_target), 1e-8);
  EXPECT_LT((result.T_camera_target.translation() - scene.T_camera_target.translation()).norm(),
            1e-8);
}

TEST(DltPose, ProjectivePathExactOnNoiseFreeVolumes) {
  std::mt19937_64 rng(1);
  for (int n : {6, 8, 20, 100}) {
    for (int trial = 0; trial < 30; ++trial) {
      const testing::PointView scene = RandomScene(rng, n, PointShape::kVolume);
      ExpectExact(DltPose(scene.object_points, scene.pixels, scene.camera), scene,
                  DltPath::kProjective);
    }
  }
}

TEST(DltPose, HomographyPathExactOnNoiseFreePlanes) {
  std::mt19937_64 rng(2);
  for (int n : {4, 5, 20, 100}) {
    for (int trial = 0; trial < 30; ++trial) {
      testing::PointView scene = RandomScene(rng, n, PointShape::kPlane);
      ExpectExact(DltPose(scene.object_points, scene.pixels, scene.camera), scene,
                  DltPath::kHomography);
      // The same board described on another plane of the target frame: P' = G P, so the pose
      // becomes T G⁻¹.
      const Pose G = testing::RandomPose(rng, 0.3);
      for (Eigen::Vector3d& P : scene.object_points) P = G * P;
      scene.T_camera_target = scene.T_camera_target * G.inverse();
      ExpectExact(DltPose(scene.object_points, scene.pixels, scene.camera), scene,
                  DltPath::kHomography);
    }
  }
}

TEST(DltPose, CloseToTheTruthUnderPixelNoise) {
  // 0.5 px on 30 points of a 0.4 m object at 1 m with f = 1000 px: the pose is determined to
  // roughly 0.1°, 1 mm; a bound 10× wider catches a wrong sign, scale or path choice.
  std::mt19937_64 rng(3);
  for (PointShape shape : {PointShape::kVolume, PointShape::kPlane}) {
    for (int trial = 0; trial < 50; ++trial) {
      const testing::PointView scene = RandomScene(rng, 30, shape);
      const DltPoseResult result = DltPose(
          scene.object_points, testing::AddPixelNoise(rng, scene.pixels, 0.5), scene.camera);
      EXPECT_LT(RotationError(result.T_camera_target, scene.T_camera_target), 0.02);
      EXPECT_LT((result.T_camera_target.translation() - scene.T_camera_target.translation()).norm(),
                0.02);
    }
  }
}

TEST(DltPose, RefusesTooFewPoints) {
  std::mt19937_64 rng(4);
  const testing::PointView volume = RandomScene(rng, 5, PointShape::kVolume);
  try {
    DltPose(volume.object_points, volume.pixels, volume.camera);
    FAIL() << "expected DegenerateError";
  } catch (const DegenerateError& e) {
    EXPECT_NE(std::string(e.what()).find("at least 6 non-coplanar"), std::string::npos) << e.what();
  }
  const testing::PointView plane = RandomScene(rng, 3, PointShape::kPlane);
  EXPECT_THROW(DltPose(plane.object_points, plane.pixels, plane.camera), DegenerateError);
}

TEST(DltPose, RefusesDegenerateConfigurations) {
  const CameraModel camera = CameraModel::Pinhole(1000.0);
  const Pose T = MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 1.0));
  const auto pixels = [&](const std::vector<Eigen::Vector3d>& object) {
    std::vector<Eigen::Vector2d> out;
    for (const Eigen::Vector3d& P : object) out.push_back(Project(camera, T * P));
    return out;
  };
  std::vector<Eigen::Vector3d> line;
  for (int k = 0; k < 8; ++k) line.emplace_back(0.02 * k, 0.01 * k, 0.0);
  EXPECT_THROW(DltPose(line, pixels(line), camera), DegenerateError);
  // Four coplanar points, three of them on one line: the homography is not determined.
  const std::vector<Eigen::Vector3d> three_on_a_line = {
      {0.0, 0.0, 0.0}, {0.1, 0.0, 0.0}, {0.2, 0.0, 0.0}, {0.05, 0.1, 0.0}};
  EXPECT_THROW(DltPose(three_on_a_line, pixels(three_on_a_line), camera), DegenerateError);
  // A plane plus one point: 8 + 2 constraints for 11 unknowns.
  std::vector<Eigen::Vector3d> plane_and_point = {{0.02, 0.03, 0.12}};
  for (int k = 0; k < 12; ++k) plane_and_point.emplace_back(0.03 * (k % 4), 0.04 * (k / 4), 0.0);
  try {
    DltPose(plane_and_point, pixels(plane_and_point), camera);
    FAIL() << "expected DegenerateError";
  } catch (const DegenerateError& e) {
    EXPECT_NE(std::string(e.what()).find("all object points but point 1"), std::string::npos)
        << e.what();
  }
}

TEST(DltPoseOptions, IsValidNamesTheField) {
  EXPECT_TRUE(testing::IsValidOptions(DltPoseOptions{}));
  EXPECT_TRUE(testing::RefusesNaming(DltPoseOptions{}, "DltPoseOptions.planarity_tolerance",
                                     [](auto& o) { o.planarity_tolerance = -1e-3; }));
  EXPECT_TRUE(testing::RefusesNaming(DltPoseOptions{}, "DltPoseOptions.planarity_tolerance",
                                     [](auto& o) { o.planarity_tolerance = std::nan(""); }));
}

}  // namespace
}  // namespace hecal::pose
