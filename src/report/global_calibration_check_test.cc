// The model check of the target-free covariance (global_calibration_check.h) against the truth
// of synthetic scenes. Where the noise model holds (arm-like scenes: 10 motions on 20 stations,
// 10° turns and 3 cm steps, 0.1 px rays, robot error 0.03° / 0.25 mm per pose; kuka2-shaped
// scenes: 27 consecutive motions on 28 stations) the check seldom inflates and the mean NEES
// stays as it is. Where it does not — each kuka2 motion's matches agree with a camera motion
// wrong by its own error (wrong but consistent matches; the model has only station errors) —
// the model's σ are far too small and the checked ones are closer to the error.
#include "hecal/report/global_calibration_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/se3.h"
#include "testing/epipolar_scenes.h"
#include "testing/kuka2_scene.h"

namespace hecal::report {
namespace {

testing::EpipolarSceneSpec ArmLikeSpec() {
  testing::EpipolarSceneSpec spec;
  spec.motions = 10;
  spec.pairs = 40;
  spec.rotation = 10.0 * M_PI / 180.0;
  spec.step = 0.03;
  spec.depth = 0.6;
  spec.pixel_sigma = 0.1;
  spec.robot_rotation_sigma = 0.03 * M_PI / 180.0;
  spec.robot_translation_sigma = 0.25e-3;
  return spec;
}

double Nees(const Pose& X, const Matrix6d& covariance, const Pose& truth) {
  const Vector6d error = se3::Log(X.inverse() * truth);
  return error.dot(covariance.inverse() * error);
}

// Σ_k (error_k / σ_k)²: the per-axis reading a user makes of the σ (mean 6 when they are right).
double AxisZ2(const Pose& X, const Matrix6d& covariance, const Pose& truth) {
  const Vector6d error = se3::Log(X.inverse() * truth);
  return error.cwiseAbs2().cwiseQuotient(covariance.diagonal()).sum();
}

struct Study {
  double model_nees = 0.0, checked_nees = 0.0;  // means
  double model_z2 = 0.0, checked_z2 = 0.0;      // means of AxisZ2
  int used = 0;                                 // scenes where the check inflated
};

Study RunArmLike(int scenes) {
  Study study;
  for (int k = 0; k < scenes; ++k) {
    testing::EpipolarScene scene = testing::MakeEpipolarScene(ArmLikeSpec(), 100 + k);
    const estimation::RobotNoisePolish polish =
        estimation::PolishWithEstimatedRobotNoise(scene.problem, scene.X);
    const GlobalCovarianceCheck checked = CheckGlobalCovariance(scene.problem, polish);
    EXPECT_TRUE(checked.check.possible) << checked.check.reason;
    study.model_nees += Nees(polish.polish.X, polish.polish.covariance, scene.X) / scenes;
    study.checked_nees += Nees(polish.polish.X, checked.covariance, scene.X) / scenes;
    study.used += checked.check.used;
    EXPECT_EQ(checked.warning.empty(), !checked.check.used);
  }
  std::printf("arm-like scenes: mean NEES model %.2f, checked %.2f; inflated in %d of %d\n",
              study.model_nees, study.checked_nees, study.used, scenes);
  return study;
}

TEST(CheckGlobalCovariance, SeldomInflatesWhereTheNoiseModelHolds) {
  const Study study = RunArmLike(10);
  EXPECT_LE(study.used, 3);
  EXPECT_GT(study.checked_nees, 6.0 - 2.0 * std::sqrt(12.0 / 10));  // not over-inflated
  EXPECT_LT(study.checked_nees, 6.0 + 3.0 * std::sqrt(12.0 / 10));
}

// Each motion's hand motion given wrong by its own error (Exp(ω), τ) on the right, independent
// between motions: the matches of a motion agree with one camera motion, not the robot's. The
// model has only station errors, whose effect on consecutive motions telescopes; this does not.
void PerturbMotions(global::EpipolarProblem* problem, double rotation, double translation,
                    std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  hecal::NormalDistribution normal(0.0, 1.0);
  for (global::EpipolarMotion& motion : problem->motions) {
    // Drawn last to first: the order these tests' data were generated in.
    const double omega_z = normal(rng), omega_y = normal(rng), omega_x = normal(rng);
    const Eigen::Vector3d omega(omega_x, omega_y, omega_z);
    const double tau_z = normal(rng), tau_y = normal(rng), tau_x = normal(rng);
    const Eigen::Vector3d tau(tau_x, tau_y, tau_z);
    motion.hand = motion.hand * MakePose(so3::Exp(rotation * omega), translation * tau);
  }
}

Study RunKuka2(double motion_rotation, double motion_translation, int scenes) {
  Study study;
  for (int k = 0; k < scenes; ++k) {
    testing::kuka2::Scene scene = testing::kuka2::MakeScene({}, 300 + k);
    PerturbMotions(&scene.problem, motion_rotation, motion_translation, 700 + k);
    const estimation::RobotNoisePolish polish =
        estimation::PolishWithEstimatedRobotNoise(scene.problem, scene.X);
    const GlobalCovarianceCheck checked = CheckGlobalCovariance(scene.problem, polish);
    EXPECT_TRUE(checked.check.possible) << checked.check.reason;
    const double model = Nees(polish.polish.X, polish.polish.covariance, scene.X);
    const double after = Nees(polish.polish.X, checked.covariance, scene.X);
    study.model_nees += model / scenes;
    study.checked_nees += after / scenes;
    const double z2 = AxisZ2(polish.polish.X, polish.polish.covariance, scene.X);
    const double z2_after = AxisZ2(polish.polish.X, checked.covariance, scene.X);
    study.model_z2 += z2 / scenes;
    study.checked_z2 += z2_after / scenes;
    study.used += checked.check.used;
  }
  std::printf(
      "kuka2, motion error %g rad %g m: mean NEES model %.2f, checked %.2f; axis z2 %.2f, %.2f; "
      "inflated in %d of %d\n",
      motion_rotation, motion_translation, study.model_nees, study.checked_nees, study.model_z2,
      study.checked_z2, study.used, scenes);
  return study;
}

// kuka2-shaped scenes (testing/kuka2_scene.h: 28 stations, 27 consecutive motions) where the
// model holds: the check seldom inflates.
TEST(CheckGlobalCovariance, SeldomInflatesOnKuka2ScenesWhereTheNoiseModelHolds) {
  const Study study = RunKuka2(0.0, 0.0, 6);
  EXPECT_LE(study.used, 1);
  EXPECT_LT(std::abs(study.checked_nees - study.model_nees), 0.5);
}

// The same scenes with each motion's hand motion wrong by its own 0.023° and 0.1 mm per axis: the
// model's σ is far too small (mean Σ z² 24 instead of 6); the check inflates in most scenes and
// brings the error in σ down, though not to 6 (measured: 24.5 → 19.0; docs/global.md).
TEST(CheckGlobalCovariance, InflatesTowardsTheErrorWhenEachMotionIsWrongByItsOwnError) {
  const Study study = RunKuka2(4e-4, 1e-4, 8);
  EXPECT_GT(study.model_z2, 15.0);  // the premise: the model's covariance is far too small
  EXPECT_GE(study.used, 6);
  EXPECT_LT(study.checked_z2, 0.85 * study.model_z2);
  EXPECT_LT(study.checked_nees, study.model_nees);
}

TEST(CheckGlobalCovariance, IsNotMadeWithTooFewStations) {
  testing::EpipolarSceneSpec spec = ArmLikeSpec();
  spec.motions = 3;  // 6 stations
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 7);
  const estimation::RobotNoisePolish polish =
      estimation::PolishWithEstimatedRobotNoise(scene.problem, scene.X);
  const GlobalCovarianceCheck checked = CheckGlobalCovariance(scene.problem, polish);
  EXPECT_FALSE(checked.check.possible);
  EXPECT_NE(checked.warning.find("6 stations, at least 7 needed"), std::string::npos)
      << checked.warning;
  EXPECT_EQ(checked.covariance, polish.polish.covariance);
}

}  // namespace
}  // namespace hecal::report
