// the linear pose paper's method: exact on noise-free data, literally the paper's estimator on
// noisy data (a transcription of eqs. 18–26 in pixels with F ≠ 1), invariant to the length unit,
// and the refusals with their advice (coplanar, a plane plus one point, too few points).
#include "hecal/pose/linear_pose.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <random>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "pose/pose_test_util.h"
#include "testing/options_validity.h"
#include "testing/pose_scenes.h"

namespace hecal::pose {
namespace {

using testing::PointShape;
using testing::RandomScene;

template <typename Call>
std::string DegenerateMessage(Call call) {
  try {
    call();
  } catch (const DegenerateError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected DegenerateError";
  return "";
}

TEST(LinearPose, ExactOnNoiseFreeData) {
  std::mt19937_64 rng(1);
  for (int n : {6, 7, 10, 50}) {
    for (int trial = 0; trial < 50; ++trial) {
      const testing::PointView scene = RandomScene(rng, n, PointShape::kVolume);
      const LinearPoseResult result = LinearPose(scene.object_points, scene.pixels, scene.camera);
      EXPECT_LT(RotationError(result.T_camera_target, scene.T_camera_target), 1e-8) << n;
      EXPECT_LT((result.T_camera_target.translation() - scene.T_camera_target.translation()).norm(),
                1e-8)
          << n;
      EXPECT_GT(result.reciprocal_condition, 1e-6);
    }
  }
}

// The linear pose paper transcribed literally in pixels (X = F x/z, P1 at the object origin, normal
// equations, eq. 23 for the scale), orthogonalised by SVD: the estimate the paper defines, here on
// noisy data where different linear estimators differ.
Pose PaperEstimate(const std::vector<Eigen::Vector3d>& object,
                   const std::vector<Eigen::Vector2d>& XY, double F) {
  const std::size_t n = object.size();
  Eigen::MatrixXd U = Eigen::MatrixXd::Zero(2 * (n - 1), 9);
  Eigen::VectorXd B(2 * (n - 1));
  for (std::size_t k = 1; k < n; ++k) {
    const Eigen::RowVector3d P = (object[k] - object[0]).transpose();  // P1 at the origin
    const Eigen::Index i = 2 * static_cast<Eigen::Index>(k - 1);
    U.block<1, 3>(i, 0) = F * P;
    U.block<1, 3>(i, 6) = -XY[k].x() * P;
    B(i) = XY[k].x() - XY[0].x();
    U.block<1, 3>(i + 1, 3) = F * P;
    U.block<1, 3>(i + 1, 6) = -XY[k].y() * P;
    B(i + 1) = XY[k].y() - XY[0].y();
  }
  const Eigen::MatrixXd UtU_inv = (U.transpose() * U).inverse();
  const double a = std::sqrt(3.0 / (B.transpose() * U * UtU_inv * UtU_inv * U.transpose() * B)(0));
  const Eigen::VectorXd R_vec = a * UtU_inv * U.transpose() * B;
  Eigen::Matrix3d R_hat;
  R_hat << R_vec(0), R_vec(1), R_vec(2), R_vec(3), R_vec(4), R_vec(5), R_vec(6), R_vec(7), R_vec(8);
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(R_hat, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d R = svd.matrixU() * svd.matrixV().transpose();
  const Eigen::Vector3d T1 = a * Eigen::Vector3d(XY[0].x() / F, XY[0].y() / F, 1.0);
  return MakePose(R, T1 - R * object[0]);
}

TEST(LinearPose, IsThePapersEstimatorOnNoisyData) {
  std::mt19937_64 rng(2);
  const double F = 1200.0;
  for (int trial = 0; trial < 100; ++trial) {
    const testing::PointView scene =
        RandomScene(rng, 12, PointShape::kVolume, CameraModel::Pinhole(F));
    const std::vector<Eigen::Vector2d> noisy = testing::AddPixelNoise(rng, scene.pixels, 1.0);
    const Pose paper = PaperEstimate(scene.object_points, noisy, F);
    const Pose ours =
        LinearPose(scene.object_points, noisy, CameraModel::Pinhole(F)).T_camera_target;
    // Noise moves both far more than this (≈ 1e-3 rad), so agreement means the same estimator.
    EXPECT_GT(RotationError(paper, scene.T_camera_target), 1e-6);
    EXPECT_LT(RotationError(ours, paper), 1e-9);
    EXPECT_LT((ours.translation() - paper.translation()).norm(), 1e-9);
  }
}

TEST(LinearPose, ObjectUnitOnlyScalesTheTranslation) {
  std::mt19937_64 rng(3);
  const testing::PointView scene = RandomScene(rng, 15, PointShape::kVolume);
  const std::vector<Eigen::Vector2d> noisy = testing::AddPixelNoise(rng, scene.pixels, 0.5);
  std::vector<Eigen::Vector3d> millimetres;
  for (const Eigen::Vector3d& P : scene.object_points) millimetres.push_back(1000.0 * P);
  const Pose in_m = LinearPose(scene.object_points, noisy, scene.camera).T_camera_target;
  const Pose in_mm = LinearPose(millimetres, noisy, scene.camera).T_camera_target;
  EXPECT_LT(RotationError(in_m, in_mm), 1e-12);
  EXPECT_LT((1000.0 * in_m.translation() - in_mm.translation()).norm(), 1e-9);
}

// A flat board plus raised points: one raised point makes U singular whichever point is P1 (see
// linear_pose.h) and is refused, naming the lone point; two raised points determine the pose,
// whichever comes first.
TEST(LinearPose, PlanePlusOnePointIsRefusedPlusTwoIsExact) {
  std::mt19937_64 rng(4);
  for (int trial = 0; trial < 20; ++trial) {
    const testing::PointView board = RandomScene(rng, 12, PointShape::kPlane);
    const auto pixel = [&](const Eigen::Vector3d& P) {
      return Project(board.camera, board.T_camera_target * P);
    };
    const Eigen::Vector3d raised(0.05, -0.02, -0.15), also_raised(-0.1, 0.08, -0.1);
    std::vector<Eigen::Vector3d> object = {raised};
    std::vector<Eigen::Vector2d> pixels = {pixel(raised)};
    object.insert(object.end(), board.object_points.begin(), board.object_points.end());
    pixels.insert(pixels.end(), board.pixels.begin(), board.pixels.end());
    const std::string message =
        DegenerateMessage([&] { LinearPose(object, pixels, board.camera); });
    EXPECT_NE(message.find("all object points but point 1 lie on one plane"), std::string::npos)
        << message;

    object.push_back(also_raised);
    pixels.push_back(pixel(also_raised));
    const LinearPoseResult result = LinearPose(object, pixels, board.camera);
    EXPECT_GT(result.reciprocal_condition, 1e-6);
    EXPECT_LT(RotationError(result.T_camera_target, board.T_camera_target), 1e-8);
    EXPECT_LT((result.T_camera_target.translation() - board.T_camera_target.translation()).norm(),
              1e-8);
  }
}

TEST(LinearPose, RefusesCoplanarPointsAndSuggestsOtherMethods) {
  std::mt19937_64 rng(5);
  testing::PointView scene = RandomScene(rng, 20, PointShape::kPlane);
  const std::string planar =
      DegenerateMessage([&] { LinearPose(scene.object_points, scene.pixels, scene.camera); });
  EXPECT_NE(planar.find("the linear method"), std::string::npos) << planar;
  EXPECT_NE(planar.find("non-coplanar"), std::string::npos) << planar;
  EXPECT_NE(planar.find("--method ippe"), std::string::npos) << planar;
  EXPECT_NE(planar.find("dlt"), std::string::npos) << planar;

  // The same board on an arbitrary plane (not z = 0) is refused too.
  const Pose T = testing::RandomPose(rng, 0.5);
  for (Eigen::Vector3d& P : scene.object_points) P = T * P;
  EXPECT_THROW(LinearPose(scene.object_points, scene.pixels, scene.camera), DegenerateError);
}

TEST(LinearPose, RefusesFewerThanSixPoints) {
  std::mt19937_64 rng(6);
  const testing::PointView scene = RandomScene(rng, 5, PointShape::kVolume);
  const std::string message =
      DegenerateMessage([&] { LinearPose(scene.object_points, scene.pixels, scene.camera); });
  EXPECT_NE(message.find("at least 6"), std::string::npos) << message;
  EXPECT_NE(message.find("got 5"), std::string::npos) << message;
}

TEST(LinearPose, RefusesAnObjectWithoutExtentInTheImage) {
  std::vector<Eigen::Vector3d> object;
  std::mt19937_64 rng(7);
  hecal::UniformRealDistribution u(-0.1, 0.1);
  for (int k = 0; k < 8; ++k) {
    const double z = u(rng), y = u(rng), x = u(rng);  // last to first, as the data were generated
    object.emplace_back(x, y, z);
  }
  const std::vector<Eigen::Vector2d> same(8, Eigen::Vector2d(0.1, 0.2));
  EXPECT_THROW(LinearPoseNormalized(object, same), DegenerateError);
}

TEST(LinearPose, RejectsMismatchedOrNonFiniteInput) {
  std::mt19937_64 rng(8);
  testing::PointView scene = RandomScene(rng, 8, PointShape::kVolume);
  std::vector<Eigen::Vector2d> fewer(scene.pixels.begin(), scene.pixels.end() - 1);
  EXPECT_THROW(LinearPose(scene.object_points, fewer, scene.camera), InputError);
  scene.object_points[3].y() = std::nan("");
  EXPECT_THROW(LinearPose(scene.object_points, scene.pixels, scene.camera), InputError);
}

TEST(LinearPoseOptions, IsValidNamesTheField) {
  EXPECT_TRUE(testing::IsValidOptions(LinearPoseOptions{}));
  EXPECT_TRUE(testing::RefusesNaming(LinearPoseOptions{}, "LinearPoseOptions.planarity_tolerance",
                                     [](auto& o) { o.planarity_tolerance = 0.0; }));
  EXPECT_TRUE(testing::RefusesNaming(LinearPoseOptions{}, "LinearPoseOptions.planarity_tolerance",
                                     [](auto& o) { o.planarity_tolerance = 1.0; }));
}

}  // namespace
}  // namespace hecal::pose
