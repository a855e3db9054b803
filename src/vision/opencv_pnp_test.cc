// OpenCV's PnP methods behind hecal's types: every method recovers a known T_camera_target from
// exact synthetic pixels (with distortion), the frame convention is x_camera = T · P, IPPE
// refuses non-planar points, the refined pose minimises the reprojection error, and bad input
// is reported.
#include "hecal/vision/opencv_pnp.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "testing/image_scene.h"
#include "testing/synthetic_views.h"

namespace hecal::vision {
namespace {

using testing::LookAt;
using testing::Project;
using testing::RotationError;
using testing::TranslationError;

pose::CameraModel TestCamera() {
  return {.fx = 900.0,
          .fy = 905.0,
          .cx = 645.0,
          .cy = 478.0,
          .width = 1280,
          .height = 960,
          .distortion = {-0.21, 0.09, 0.0012, -0.0007, -0.015}};
}

// The inner corners of a 9 × 6 chessboard of 30 mm squares, the first corner the origin.
std::vector<Eigen::Vector3d> PnpBoard() {
  return ::hecal::testing::GridPoints({.cols = 9, .rows = 6, .pitch = 0.03, .centred = false});
}

// A 9 × 6 board (30 mm squares) seen from 0.5 m, tilted 35° about a skew axis.
Pose PlanarTruth() {
  return LookAt(Eigen::Vector3d(0.35, -0.15, -0.45), Eigen::Vector3d(0.12, 0.075, 0.0),
                Eigen::Vector2d(0.05, -0.08));
}

// Random points in a 0.3 m cube centred 0.8 m in front of the camera (target frame = camera
// frame shifted and turned).
std::vector<Eigen::Vector3d> CubePoints(int n, std::mt19937_64& rng) {
  hecal::UniformRealDistribution u(-0.15, 0.15);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < n; ++k) {
    const double z = u(rng), y = u(rng), x = u(rng);  // last to first, as the data were generated
    points.emplace_back(x, y, z);
  }
  return points;
}

Pose VolumeTruth() {
  return MakePose(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -2, 0.5).normalized()).matrix(),
                  Eigen::Vector3d(0.05, -0.03, 0.8));
}

double ReprojectionRms(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<Eigen::Vector2d>& pixels, const Pose& T,
                       const pose::CameraModel& camera) {
  const std::vector<Eigen::Vector2d> predicted = Project(points, T, camera);
  double sum = 0.0;
  for (std::size_t k = 0; k < pixels.size(); ++k) sum += (predicted[k] - pixels[k]).squaredNorm();
  return std::sqrt(sum / static_cast<double>(pixels.size()));
}

TEST(OpenCvPnp, EveryMethodRecoversAPlanarPoseExactly) {
  const pose::CameraModel camera = TestCamera();
  const std::vector<Eigen::Vector3d> board = PnpBoard();
  const Pose truth = PlanarTruth();
  const std::vector<Eigen::Vector2d> pixels = Project(board, truth, camera);
  for (const PnpMethodInfo& info : OpenCvPnpMethods()) {
    const Pose T = SolvePnPOpenCv(info.method, board, pixels, camera);
    // Exact pixels: every method is exact to ~1e-9 (measured: EPnP 7e-9 rad, the others less).
    EXPECT_LT(RotationError(T, truth), 1e-7) << info.name;
    EXPECT_LT(TranslationError(T, truth), 1e-7) << info.name;
  }
}

TEST(OpenCvPnp, PoseMapsTargetPointsIntoTheCameraFrame) {
  // Frame convention, independently of any solver: the target's origin lands where the pose's
  // translation says, and the first corner's pixel is that point's projection.
  const pose::CameraModel camera = TestCamera();
  const std::vector<Eigen::Vector3d> board = PnpBoard();
  const Pose truth = PlanarTruth();
  const std::vector<Eigen::Vector2d> pixels = Project(board, truth, camera);
  const Pose T = SolvePnPOpenCv(PnpMethod::kIppe, board, pixels, camera);
  const Eigen::Vector3d origin_camera = T * board[0];
  EXPECT_GT(origin_camera.z(), 0.0);
  EXPECT_NEAR((origin_camera - truth.translation()).norm(), 0.0, 1e-8);
}

TEST(OpenCvPnp, IppeAcceptsAnyPlaneNotOnlyZEqualsZero) {
  const pose::CameraModel camera = TestCamera();
  // The board turned 30° about x and lifted: still coplanar, but z != 0.
  const Pose T_board_moved = MakePose(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()).matrix(),
                                      Eigen::Vector3d(0, 0, 0.1));
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3d& p : PnpBoard()) points.push_back(T_board_moved * p);
  ASSERT_TRUE(AreCoplanar(points));
  const Pose truth = PlanarTruth() * T_board_moved.inverse();
  const Pose T = SolvePnPOpenCv(PnpMethod::kIppe, points, Project(points, truth, camera), camera);
  EXPECT_LT(RotationError(T, truth), 1e-8);
  EXPECT_LT(TranslationError(T, truth), 1e-8);
}

TEST(OpenCvPnp, NonPlanarMethodsRecoverAVolumePose) {
  const pose::CameraModel camera = TestCamera();
  std::mt19937_64 rng(7);
  const std::vector<Eigen::Vector3d> points = CubePoints(20, rng);
  ASSERT_FALSE(AreCoplanar(points));
  const Pose truth = VolumeTruth();
  const std::vector<Eigen::Vector2d> pixels = Project(points, truth, camera);
  for (const PnpMethodInfo& info : OpenCvPnpMethods()) {
    if (info.planar_only) continue;
    const Pose T = SolvePnPOpenCv(info.method, points, pixels, camera);
    EXPECT_LT(RotationError(T, truth), 1e-7) << info.name;
    EXPECT_LT(TranslationError(T, truth), 1e-7) << info.name;
  }
  const Pose refined = SolvePnPOpenCvRefined(points, pixels, camera);
  EXPECT_LT(RotationError(refined, truth), 1e-8);
  EXPECT_LT(TranslationError(refined, truth), 1e-8);
}

TEST(OpenCvPnp, IppeRefusesNonPlanarPoints) {
  const pose::CameraModel camera = TestCamera();
  std::mt19937_64 rng(3);
  const std::vector<Eigen::Vector3d> points = CubePoints(12, rng);
  const std::vector<Eigen::Vector2d> pixels = Project(points, VolumeTruth(), camera);
  try {
    SolvePnPOpenCv(PnpMethod::kIppe, points, pixels, camera);
    FAIL() << "ippe accepted non-planar points";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "PnpMethod ippe");
    EXPECT_NE(e.problem().find("coplanar"), std::string::npos) << e.what();
    EXPECT_NE(e.fix().find("sqpnp"), std::string::npos) << e.what();
  }
}

TEST(OpenCvPnp, RefinedPoseMinimisesTheReprojectionErrorUnderNoise) {
  const pose::CameraModel camera = TestCamera();
  const std::vector<Eigen::Vector3d> board = PnpBoard();
  const Pose truth = PlanarTruth();
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Eigen::Vector2d> pixels = Project(board, truth, camera);
    testing::AddNoise(0.5, rng, &pixels);
    const Pose ippe = SolvePnPOpenCv(PnpMethod::kIppe, board, pixels, camera);
    const Pose refined = SolvePnPOpenCvRefined(board, pixels, camera);
    // LM from IPPE cannot end worse than its start, and is at a minimum: the truth itself (a
    // feasible point) reprojects no better.
    const double refined_rms = ReprojectionRms(board, pixels, refined, camera);
    EXPECT_LE(refined_rms, ReprojectionRms(board, pixels, ippe, camera) + 1e-12);
    EXPECT_LE(refined_rms, ReprojectionRms(board, pixels, truth, camera) + 1e-12);
    // 0.5 px noise on 54 points 0.5 m away: the pose is good to well under a degree / 5 mm.
    EXPECT_LT(RotationError(refined, truth), 0.5 * std::numbers::pi / 180.0);
    EXPECT_LT(TranslationError(refined, truth), 0.005);
  }
}

TEST(OpenCvPnp, MethodNamesRoundTrip) {
  ASSERT_EQ(OpenCvPnpMethods().size(), 4u);
  for (const PnpMethodInfo& info : OpenCvPnpMethods()) {
    EXPECT_EQ(ParsePnpMethod(info.name), info.method);
    EXPECT_EQ(Info(info.method).name, info.name);
  }
  EXPECT_EQ(ParsePnpMethod("ippe"), PnpMethod::kIppe);
  EXPECT_EQ(ParsePnpMethod("sqpnp"), PnpMethod::kSqpnp);
  EXPECT_EQ(ParsePnpMethod("epnp"), PnpMethod::kEpnp);
  EXPECT_EQ(ParsePnpMethod("iterative"), PnpMethod::kIterative);
  EXPECT_FALSE(ParsePnpMethod("IPPE").has_value());
  EXPECT_FALSE(ParsePnpMethod("p3p").has_value());
}

TEST(OpenCvPnp, BadInputIsReported) {
  const pose::CameraModel camera = TestCamera();
  const std::vector<Eigen::Vector3d> board = PnpBoard();
  std::vector<Eigen::Vector2d> pixels = Project(board, PlanarTruth(), camera);

  std::vector<Eigen::Vector2d> short_pixels(pixels.begin(), pixels.end() - 1);
  EXPECT_THROW(SolvePnPOpenCv(PnpMethod::kSqpnp, board, short_pixels, camera), InputError);

  const std::vector<Eigen::Vector3d> three(board.begin(), board.begin() + 3);
  const std::vector<Eigen::Vector2d> three_pixels(pixels.begin(), pixels.begin() + 3);
  EXPECT_THROW(SolvePnPOpenCv(PnpMethod::kEpnp, three, three_pixels, camera), InputError);

  // One row of the board: every point on a line.
  const std::vector<Eigen::Vector3d> row(board.begin(), board.begin() + 9);
  const std::vector<Eigen::Vector2d> row_pixels(pixels.begin(), pixels.begin() + 9);
  EXPECT_THROW(SolvePnPOpenCv(PnpMethod::kSqpnp, row, row_pixels, camera), DegenerateError);

  pixels[4].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SolvePnPOpenCv(PnpMethod::kIppe, board, pixels, camera), InputError);

  pose::CameraModel no_focal = camera;
  no_focal.fx = 0.0;
  EXPECT_THROW(
      SolvePnPOpenCv(PnpMethod::kIppe, board, Project(board, PlanarTruth(), camera), no_focal),
      InputError);

  // Iterative without a start needs 6 non-coplanar points for its DLT.
  std::mt19937_64 rng(5);
  const std::vector<Eigen::Vector3d> five = CubePoints(5, rng);
  EXPECT_THROW(
      SolvePnPOpenCv(PnpMethod::kIterative, five, Project(five, VolumeTruth(), camera), camera),
      InputError);
}

}  // namespace
}  // namespace hecal::vision
