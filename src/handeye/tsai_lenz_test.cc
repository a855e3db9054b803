#include "hecal/handeye/tsai_lenz.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"
#include "testing/scene.h"

namespace hecal::handeye {
namespace {

// Thesis-like stations (±45° tilt, free spin, 1 m from the target) with X's rotation angle fixed
// to `x_angle`, σ = 0.3 mm / 0.3° on robot and camera.
testing::Scene NoisyCaseWithXAngle(double x_angle, int stations, uint64_t seed) {
  std::mt19937_64 rng(seed);
  hecal::UniformRealDistribution tilt(-45.0 * kRadiansPerDegree, 45.0 * kRadiansPerDegree);
  hecal::UniformRealDistribution spin(-std::numbers::pi, std::numbers::pi);
  std::vector<Pose> T_target_camera;
  for (int i = 0; i < stations; ++i) {
    // Drawn last to first: the order these tests' data were generated in.
    const double rz = spin(rng);
    const double ry = tilt(rng);
    const double rx = tilt(rng);
    const Eigen::Matrix3d R = so3::Exp(rx * Eigen::Vector3d::UnitX()) *
                              so3::Exp(ry * Eigen::Vector3d::UnitY()) *
                              so3::Exp(rz * Eigen::Vector3d::UnitZ());
    T_target_camera.push_back(
        MakePose(R, Eigen::Vector3d(0.0, 0.0, -1.0) + testing::RandomPose(rng, 0.5).translation()));
  }
  testing::Scene data = testing::CaseFromCameraPoses(Setup::kEyeInHand, T_target_camera, rng);
  // Re-pose the robot for the chosen X (Z = A X B).
  data.X.linear() = so3::Exp(testing::RandomRotationVector(rng, x_angle));
  const testing::PoseNoise noise{0.3 * kRadiansPerDegree, 0.3e-3};
  for (int i = 0; i < stations; ++i) {
    data.T_base_gripper_true[i] = data.Z * T_target_camera[i] * data.X.inverse();
    data.T_base_gripper[i] = testing::AddPoseNoise(data.T_base_gripper_true[i], noise, rng);
    data.T_camera_target[i] = testing::AddPoseNoise(data.T_camera_target_true[i], noise, rng);
  }
  return data;
}

// X a half-turn (or nearly): P'_X = tan(θ_X/2) n_X is infinite at π, so a literal Tsai–Lenz
// solve is ill-conditioned there; in the pre-rotated frame the noisy error stays at the level of
// the noise, as for any other X.
TEST(TsaiLenz, NoisyDataWithXNearHalfTurnStayAccurate) {
  for (double x_angle : {std::numbers::pi, std::numbers::pi - 1e-3 * kRadiansPerDegree, 1.0}) {
    double worst = 0.0;
    for (uint64_t seed = 1; seed <= 40; ++seed) {
      const testing::Scene data = NoisyCaseWithXAngle(x_angle, 8, seed);
      const Pose X = SolveTsaiLenz(AllPairMotions(data.MeasuredProblem()));
      worst = std::max(worst, testing::Degrees(testing::Error(X, data.X).rotation));
    }
    std::printf("X angle %.5f deg: worst rotation error %.3f deg over 40 noisy data sets\n",
                x_angle / kRadiansPerDegree, worst);
    EXPECT_LT(worst, 2.0) << x_angle;
  }
}

// Stations that only translate add motions with P_A ≈ P_B ≈ 0 (noise only): their rows vanish
// with sin(θ/2), so twenty of them next to eight rotating stations cost no accuracy.
TEST(TsaiLenz, PureTranslationStationsAreHarmless) {
  double worst_with = 0.0, worst_without = 0.0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    testing::Scene data = NoisyCaseWithXAngle(2.0, 8, seed);
    worst_without = std::max(
        worst_without,
        testing::Error(SolveTsaiLenz(AllPairMotions(data.MeasuredProblem())), data.X).rotation);
    std::mt19937_64 rng(seed);
    const testing::PoseNoise noise{0.3 * kRadiansPerDegree, 0.3e-3};
    for (int k = 0; k < 20; ++k) {  // same orientation as station 0, moved by up to 10 cm
      const Pose shift =
          MakePose(Eigen::Matrix3d::Identity(), testing::RandomPose(rng, 0.1).translation());
      const Pose T_target_camera = data.T_camera_target_true[0].inverse() * shift;
      const Pose A = data.Z * T_target_camera * data.X.inverse();
      data.T_base_gripper.push_back(testing::AddPoseNoise(A, noise, rng));
      data.T_camera_target.push_back(testing::AddPoseNoise(T_target_camera.inverse(), noise, rng));
    }
    worst_with = std::max(
        worst_with,
        testing::Error(SolveTsaiLenz(AllPairMotions(data.MeasuredProblem())), data.X).rotation);
  }
  std::printf("worst rotation error: %.3f deg without, %.3f deg with 20 pure translations\n",
              testing::Degrees(worst_without), testing::Degrees(worst_with));
  EXPECT_LT(worst_with, 1.5 * worst_without);
}

}  // namespace
}  // namespace hecal::handeye
