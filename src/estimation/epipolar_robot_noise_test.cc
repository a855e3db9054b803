// The polish with the robot's pose error in the model, against synthetic scenes with a known
// robot error like a real arm's (0.03°, 0.25 mm per pose; rwhe-kuka2's SOURCE.md): the noise
// levels it estimates, and the covariance of X over many scenes (NEES against the truth), also
// per axis on rwhe-kuka2's near-degenerate motions (testing/kuka2_scene.h).
#include "hecal/estimation/epipolar_robot_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "testing/epipolar_scenes.h"
#include "testing/kuka2_scene.h"

namespace hecal::estimation {
namespace {

// Motions like a hand–eye data set: 10° rotations, 3 cm steps, points 0.6 m away, 0.1 px rays.
testing::EpipolarSceneSpec ArmLikeSpec() {
  testing::EpipolarSceneSpec spec;
  spec.motions = 10;
  spec.pairs = 40;
  spec.rotation = 10.0 * kRadiansPerDegree;
  spec.step = 0.03;
  spec.depth = 0.6;
  spec.pixel_sigma = 0.1;
  spec.robot_rotation_sigma = 0.03 * kRadiansPerDegree;
  spec.robot_translation_sigma = 0.25e-3;
  return spec;
}

std::string Fmt(const Eigen::VectorXd& v) {
  std::string out = "(";
  for (Eigen::Index k = 0; k < v.size(); ++k) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%s%.2f", k > 0 ? ", " : "", v[k]);
    out += buffer;
  }
  return out + ")";
}

double Nees(const EpipolarPolish& polish, const Pose& truth) {
  const Vector6d error = se3::Log(polish.X.inverse() * truth);
  return error.dot(polish.covariance.inverse() * error);
}

// The robot-error polish over `trials` scenes of `spec`: mean NEES against the truth (and of the
// independent-pairs polish), mean estimated noise levels.
struct NeesStudy {
  double mean_nees = 0.0, plain_mean_nees = 0.0;
  double rotation_sigma = 0.0, translation_sigma = 0.0, ray_sigma = 0.0;  // means
  double gripper_distance_squared = 0.0;  // mean |t|² of T_base_gripper over the stations, m²
};

NeesStudy RunNeesStudy(const testing::EpipolarSceneSpec& spec, int trials) {
  NeesStudy study;
  for (int trial = 0; trial < trials; ++trial) {
    const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 500 + trial);
    const EpipolarPolish plain = PolishEpipolar(scene.problem, scene.X);
    const RobotNoisePolish robot = PolishWithEstimatedRobotNoise(scene.problem, plain.X);
    EXPECT_EQ(robot.stations, 2 * spec.motions);
    study.mean_nees += Nees(robot.polish, scene.X) / trials;
    study.plain_mean_nees += Nees(plain, scene.X) / trials;
    study.rotation_sigma += robot.noise.robot_rotation_sigma / trials;
    study.translation_sigma += robot.noise.robot_translation_sigma / trials;
    study.ray_sigma += robot.noise.ray_sigma / trials;
    for (const Pose& G : scene.T_base_gripper) {
      study.gripper_distance_squared +=
          G.translation().squaredNorm() / (trials * double(scene.T_base_gripper.size()));
    }
  }
  std::printf(
      "%s, %d scenes: mean NEES %.2f (independent pairs: %.2f); mean estimated robot noise %.4f "
      "deg, %.3f mm, ray %.3f px\n",
      spec.setup == handeye::Setup::kEyeInHand ? "eye-in-hand" : "eye-to-hand", trials,
      study.mean_nees, study.plain_mean_nees, study.rotation_sigma / kRadiansPerDegree,
      1e3 * study.translation_sigma, study.ray_sigma * spec.focal);
  return study;
}

TEST(PolishWithEstimatedRobotNoise, CovarianceHoldsOverManyScenesWhereTheIndependentOneFails) {
  const testing::EpipolarSceneSpec spec = ArmLikeSpec();
  const int trials = 50;
  const NeesStudy study = RunNeesStudy(spec, trials);
  // The mean of 50 χ²₆ values: standard deviation sqrt(12/50) = 0.49; a band of 4 of them.
  EXPECT_NEAR(study.mean_nees, 6.0, 4.0 * std::sqrt(12.0 / trials));
  // The premise: with independent pairs the covariance is far too small here.
  EXPECT_GT(study.plain_mean_nees, 3.0 * 6.0);
  // The noise levels, on average over the scenes, within 30% of the truth.
  EXPECT_NEAR(study.rotation_sigma, spec.robot_rotation_sigma, 0.3 * spec.robot_rotation_sigma);
  EXPECT_NEAR(study.translation_sigma, spec.robot_translation_sigma,
              0.3 * spec.robot_translation_sigma);
  EXPECT_NEAR(study.ray_sigma, spec.pixel_sigma / spec.focal, 0.3 * spec.pixel_sigma / spec.focal);
}

// Eye-to-hand, the same protocol. The robot's error is a right perturbation of T_base_gripper;
// the model's nuisance is a right perturbation of H = T_base_gripper⁻¹, so H̃ = H·Exp(−Ad(G)·δ):
// the same rotation noise (rotated), and a translation noise with the lever arm of the gripper's
// position added (σ_r·|t_G|, correlated with the rotation), which the model's isotropic σ_t
// absorbs. The covariance must still hold; σ_t is then not the robot's own.
TEST(PolishWithEstimatedRobotNoise, CovarianceHoldsOverManyEyeToHandScenes) {
  testing::EpipolarSceneSpec spec = ArmLikeSpec();
  spec.setup = handeye::Setup::kEyeToHand;
  const int trials = 50;
  const NeesStudy study = RunNeesStudy(spec, trials);
  EXPECT_NEAR(study.mean_nees, 6.0, 4.0 * std::sqrt(12.0 / trials));
  EXPECT_GT(study.plain_mean_nees, 3.0 * 6.0);
  EXPECT_NEAR(study.rotation_sigma, spec.robot_rotation_sigma, 0.3 * spec.robot_rotation_sigma);
  EXPECT_NEAR(study.ray_sigma, spec.pixel_sigma / spec.focal, 0.3 * spec.pixel_sigma / spec.focal);
  // σ_t of H per axis: σ_t² + σ_r² (|t_G|² I − t_G t_Gᵀ) averaged over the axes.
  const double lever = std::sqrt(spec.robot_translation_sigma * spec.robot_translation_sigma +
                                 2.0 / 3.0 * spec.robot_rotation_sigma * spec.robot_rotation_sigma *
                                     study.gripper_distance_squared);
  std::printf("eye-to-hand: sigma_t of H expected %.3f mm (robot %.3f mm, |t_G| %.2f m)\n",
              1e3 * lever, 1e3 * spec.robot_translation_sigma,
              std::sqrt(study.gripper_distance_squared));
  EXPECT_NEAR(study.translation_sigma, lever, 0.3 * lever);
}

// The robot's noise given (as --robot-sigma gives it, mapped to the hand pose by HandPoseSigma)
// and held: only the ray σ is estimated, and the covariance of X is consistent with the truth
// over many scenes, in both setups.
TEST(PolishWithEstimatedRobotNoise, CovarianceWithTheRobotNoiseGivenHoldsOverManyScenes) {
  for (const handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    testing::EpipolarSceneSpec spec = ArmLikeSpec();
    spec.setup = setup;
    const PoseSigma robot{spec.robot_rotation_sigma, spec.robot_translation_sigma};
    const int trials = 30;
    double nees_sum = 0.0, ray_sigma_sum = 0.0;
    for (int trial = 0; trial < trials; ++trial) {
      const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 700 + trial);
      double mean_squared_distance = 0.0;
      for (const Pose& G : scene.T_base_gripper) {
        mean_squared_distance +=
            G.translation().squaredNorm() / double(scene.T_base_gripper.size());
      }
      const PoseSigma hand = HandPoseSigma(setup, robot, mean_squared_distance);
      const EpipolarPolish plain = PolishEpipolar(scene.problem, scene.X);
      const RobotNoisePolish given = PolishWithEstimatedRobotNoise(
          scene.problem, plain.X, std::numeric_limits<double>::infinity(), hand);
      EXPECT_TRUE(given.robot_given);
      EXPECT_EQ(given.noise.robot_rotation_sigma, hand.rotation);
      EXPECT_EQ(given.noise.robot_translation_sigma, hand.translation);
      nees_sum += Nees(given.polish, scene.X);
      ray_sigma_sum += given.noise.ray_sigma;
    }
    const double mean_nees = nees_sum / trials;
    std::printf("%s, %d scenes, robot noise given: mean NEES %.2f, mean ray %.3f px\n",
                setup == handeye::Setup::kEyeInHand ? "eye-in-hand" : "eye-to-hand", trials,
                mean_nees, ray_sigma_sum / trials * spec.focal);
    // The mean of 30 χ²₆ values: standard deviation sqrt(12/30) = 0.63; a band of 4 of them.
    EXPECT_NEAR(mean_nees, 6.0, 4.0 * std::sqrt(12.0 / trials));
    EXPECT_NEAR(ray_sigma_sum / trials, spec.pixel_sigma / spec.focal,
                0.3 * spec.pixel_sigma / spec.focal);
  }
}

TEST(HandPoseSigma, IsTheRobotsEyeInHandAndAddsTheLeverArmEyeToHand) {
  const PoseSigma robot{1e-3, 2e-4};
  const PoseSigma in_hand = HandPoseSigma(handeye::Setup::kEyeInHand, robot, 0.64);
  EXPECT_EQ(in_hand.rotation, robot.rotation);
  EXPECT_EQ(in_hand.translation, robot.translation);
  // |t| = 0.8 m: (2e-4)² + ⅔ (1e-3 · 0.8)² m².
  const PoseSigma to_hand = HandPoseSigma(handeye::Setup::kEyeToHand, robot, 0.64);
  EXPECT_EQ(to_hand.rotation, robot.rotation);
  EXPECT_NEAR(to_hand.translation, std::sqrt(4e-8 + 2.0 / 3.0 * 0.64e-6), 1e-15);
}

// rwhe-kuka2's motions (18 of 27 pure rotations about the gripper's x axis, which leave t's x
// component to the 9 translating ones): the covariance must hold per axis, not only on average.
// Read t in the gripper frame (Cov t = R̂ Cov(v) R̂ᵀ): the camera's z axis is the gripper's x
// here, so the per-axis σ of v (the camera frame) is not the σ of t's x component.
TEST(PolishWithEstimatedRobotNoise, CovarianceHoldsPerAxisOnKuka2ShapedMotions) {
  const testing::kuka2::SceneSpec spec;
  const int trials = 20;
  Vector6d z2 = Vector6d::Zero();  // mean z² per axis of δ = (ω, v)
  Eigen::Vector3d z2_gripper = Eigen::Vector3d::Zero();
  double translation_sigma_sum = 0.0;
  for (int trial = 0; trial < trials; ++trial) {
    const testing::kuka2::Scene scene = testing::kuka2::MakeScene(spec, 40 + trial);
    const EpipolarPolish plain = PolishEpipolar(scene.problem, scene.X);
    const RobotNoisePolish robot = PolishWithEstimatedRobotNoise(scene.problem, plain.X, 2.0);
    const Matrix6d& C = robot.polish.covariance;
    const Vector6d error = se3::Log(robot.polish.X.inverse() * scene.X);
    z2 += error.cwiseAbs2().cwiseQuotient(C.diagonal()) / trials;
    const Eigen::Matrix3d R = robot.polish.X.linear();
    const Eigen::Matrix3d C_t = R * C.bottomRightCorner<3, 3>() * R.transpose();
    const Eigen::Vector3d dt = robot.polish.X.translation() - scene.X.translation();
    z2_gripper += dt.cwiseAbs2().cwiseQuotient(C_t.diagonal()) / trials;
    translation_sigma_sum += robot.noise.robot_translation_sigma;
  }
  std::printf("%d kuka2-shaped scenes: mean z2 of delta %s; of t, gripper frame %s\n", trials,
              Fmt(z2).c_str(), Fmt(z2_gripper).c_str());
  // The mean of 20 χ²₁ values: standard deviation sqrt(2/20) = 0.32; a band of 4 of them.
  const double band = 4.0 * std::sqrt(2.0 / trials);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(z2[k], 1.0, band) << "axis " << k;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(z2_gripper[k], 1.0, band) << "gripper axis " << k;
  EXPECT_NEAR(translation_sigma_sum / trials, spec.robot_translation_sigma,
              0.2 * spec.robot_translation_sigma);
}

TEST(PolishWithRobotNoise, WithoutRobotNoiseIsThePlainPolish) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 4;
  spec.pairs = 30;
  spec.pixel_sigma = 0.5;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 12);
  const double sigma = spec.pixel_sigma / spec.focal;
  const EpipolarPolish plain = PolishEpipolar(scene.problem, scene.X, sigma);
  const EpipolarPolish gls = PolishWithRobotNoise(scene.problem, scene.X, {sigma, 0.0, 0.0});
  EXPECT_LT(se3::Log(plain.X.inverse() * gls.X).norm(), 1e-9);
  EXPECT_LT((plain.covariance - gls.covariance).norm(), 1e-6 * plain.covariance.norm());
}

TEST(EstimateEpipolarNoise, FindsNoRobotNoiseWhereThereIsNone) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 8;
  spec.pairs = 40;
  spec.pixel_sigma = 0.5;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 3);
  const EpipolarPolish plain = PolishEpipolar(scene.problem, scene.X);
  const EpipolarNoise noise = EstimateEpipolarNoise(scene.problem, plain.X);
  const double ray = spec.pixel_sigma / spec.focal;
  EXPECT_NEAR(noise.ray_sigma, ray, 0.15 * ray);
  // A robot error of 0.005° (a tenth of the ray noise) or 0.05 mm would show.
  EXPECT_LT(noise.robot_rotation_sigma, 0.1 * ray);
  EXPECT_LT(noise.robot_translation_sigma, 5e-5);
}

TEST(PolishWithRobotNoise, RefusesTooFewPairs) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 1;
  spec.pairs = 6;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 2);
  EXPECT_THROW(PolishWithEstimatedRobotNoise(scene.problem, scene.X), DegenerateError);
}

// Motions that only rotate the hand about its own origin (robot translation 0) observe the
// direction of X's translation, not its length: the polish must refuse, not return a drifted X.
TEST(PolishWithRobotNoise, RefusesMotionsThatDoNotObserveTheTranslationLength) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 8;
  spec.pairs = 30;
  spec.step = 0.0;
  spec.pixel_sigma = 0.5;
  spec.robot_rotation_sigma = 4e-4;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 5);
  EXPECT_THROW(PolishWithEstimatedRobotNoise(scene.problem, scene.X, 2.0), DegenerateError);
  // The same scene with translating motions is accepted.
  spec.step = 0.3;
  const testing::EpipolarScene moving = testing::MakeEpipolarScene(spec, 5);
  EXPECT_NO_THROW(PolishWithEstimatedRobotNoise(moving.problem, moving.X, 2.0));
}

}  // namespace
}  // namespace hecal::estimation
