#include "hecal/estimation/station_covariance.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <stdexcept>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/estimation/loop_residual.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/types.h"
#include "hecal/sim/noise.h"
#include "testing/handeye_cases.h"

namespace hecal::estimation {
namespace {

// Monte Carlo covariance of r = Log(Z⁻¹ Ã X B̃) at the truth, with Ã built from a noisy robot pose
// the way MakeProblem does (so the eye-to-hand inverse is exercised), and B̃ a noisy camera pose.
Matrix6d MonteCarloCovariance(const testing::Scene& data, int station, const PoseSigma& robot,
                              const PoseSigma& camera, int samples, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const sim::NoiseModel robot_noise{sim::NoiseModel::Kind::kGaussian, robot.rotation,
                                    robot.translation};
  const sim::NoiseModel camera_noise{sim::NoiseModel::Kind::kGaussian, camera.rotation,
                                     camera.translation};
  Matrix6d sum = Matrix6d::Zero();
  for (int s = 0; s < samples; ++s) {
    const Pose G = sim::AddNoise(data.T_base_gripper_true[station], robot_noise, rng);
    const Pose B = sim::AddNoise(data.T_camera_target_true[station], camera_noise, rng);
    const handeye::Problem noisy = handeye::MakeProblem(data.setup, {G}, {B});
    const Vector6d r = LoopResidual(noisy.A[0], noisy.B[0], data.X, data.Z);
    sum += r * r.transpose();
  }
  return sum / samples;
}

// Whitened by the model, the Monte Carlo covariance must be the identity within sampling error
// (entries of a unit-covariance sample covariance have standard deviation ≤ √(2/N) ≈ 0.014 for
// N = 10⁴; 0.06 is > 4σ) plus the O(σ) nonlinearity neglected by the first-order model.
void ExpectWhitenedIdentity(const Matrix6d& model, const Matrix6d& monte_carlo, double tolerance) {
  const Matrix6d W = WhiteningMatrix(model);
  const Matrix6d whitened = W * monte_carlo * W.transpose();
  EXPECT_LT((whitened - Matrix6d::Identity()).cwiseAbs().maxCoeff(), tolerance) << whitened;
}

class StationCovarianceTest : public ::testing::TestWithParam<handeye::Setup> {};

TEST_P(StationCovarianceTest, MatchesMonteCarloForRobotCameraAndBothNoise) {
  const handeye::Setup setup = GetParam();
  const testing::Scene data = testing::ThesisCase(setup, 4, 11);
  const handeye::Problem truth = data.MeasuredProblem();
  const PoseSigma zero;
  const PoseSigma robot{0.5 * kRadiansPerDegree, 1e-3};
  const PoseSigma camera{0.3 * kRadiansPerDegree, 2e-3};
  for (int station = 0; station < 4; ++station) {
    const Pose& A = truth.A[station];
    const Pose& B = truth.B[station];
    // Robot noise alone needs a tiny camera noise to keep Σ invertible for the whitening.
    const PoseSigma tiny{1e-4 * kRadiansPerDegree, 1e-6};
    ExpectWhitenedIdentity(StationCovariance(setup, A, B, data.X, robot, tiny),
                           MonteCarloCovariance(data, station, robot, tiny, 10000, 100 + station),
                           0.06);
    ExpectWhitenedIdentity(StationCovariance(setup, A, B, data.X, zero, camera),
                           MonteCarloCovariance(data, station, zero, camera, 10000, 200 + station),
                           0.06);
    ExpectWhitenedIdentity(StationCovariance(setup, A, B, data.X, robot, camera),
                           MonteCarloCovariance(data, station, robot, camera, 10000, 300 + station),
                           0.06);
  }
}

INSTANTIATE_TEST_SUITE_P(BothSetups, StationCovarianceTest,
                         ::testing::Values(handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand));

// Negative control: the eye-in-hand propagation applied to eye-to-hand data (noise on the wrong
// side of A_i) is detectably wrong — so the test above can fail.
// PnP-shaped camera noise (sim/noise.h: in the camera frame, tilt 2σ, spin 0.1σ, lateral 0.5σ,
// depth 5σ) is the isotropic camera components at the spin / lateral variance plus the tilt and
// depth excess at the rest: the whitened Monte Carlo covariance is the identity (as above).
TEST(StationCovariance, TiltAndDepthExcessMatchPnpShapedNoise) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::Scene data = testing::ThesisCase(setup, 4, 5, 0.0, 0.0);
    const double sr = 0.5 * kRadiansPerDegree, st = 1e-3;
    const sim::NoiseModel pnp{sim::NoiseModel::Kind::kPnp, sr, st};
    std::mt19937_64 rng(7);
    for (int station = 0; station < 4; ++station) {
      const handeye::Problem truth = handeye::MakeProblem(
          setup, {data.T_base_gripper_true[station]}, {data.T_camera_target_true[station]});
      Matrix6d sum = Matrix6d::Zero();
      const int samples = 10000;
      for (int s = 0; s < samples; ++s) {
        const Pose B = sim::AddNoise(data.T_camera_target_true[station], pnp, rng);
        const Vector6d r = LoopResidual(truth.A[0], B, data.X, data.Z);
        sum += r * r.transpose();
      }
      const NoiseComponents Q = StationNoiseComponents(setup, truth.A[0], truth.B[0], data.X);
      const NoiseVariances variances = {0.0,
                                        0.0,
                                        std::pow(0.1 * sr, 2),
                                        std::pow(0.5 * st, 2),
                                        std::pow(2.0 * sr, 2) - std::pow(0.1 * sr, 2),
                                        std::pow(5.0 * st, 2) - std::pow(0.5 * st, 2)};
      ExpectWhitenedIdentity(CombineComponents(Q, variances), sum / samples, 0.06);
    }
  }
}

TEST(StationCovariance, WrongSideOfTheRobotPoseIsDetected) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeToHand, 2, 12);
  const handeye::Problem truth = data.MeasuredProblem();
  const PoseSigma robot{0.5 * kRadiansPerDegree, 1e-3};
  const PoseSigma camera{0.3 * kRadiansPerDegree, 2e-3};
  const Matrix6d wrong =
      StationCovariance(handeye::Setup::kEyeInHand, truth.A[0], truth.B[0], data.X, robot, camera);
  const Matrix6d W = WhiteningMatrix(wrong);
  const Matrix6d whitened =
      W * MonteCarloCovariance(data, 0, robot, camera, 10000, 7) * W.transpose();
  EXPECT_GT((whitened - Matrix6d::Identity()).cwiseAbs().maxCoeff(), 0.5);
}

TEST(StationCovariance, ComponentsAreLinearInTheVariances) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeInHand, 3, 13);
  const handeye::Problem truth = data.MeasuredProblem();
  const PoseSigma robot{0.01, 0.002};
  const PoseSigma camera{0.02, 0.001};
  const NoiseComponents Q = StationNoiseComponents(truth.setup, truth.A[1], truth.B[1], data.X);
  const Matrix6d combined = CombineComponents(Q, Variances(robot, camera));
  EXPECT_LT(
      (combined - StationCovariance(truth.setup, truth.A[1], truth.B[1], data.X, robot, camera))
          .norm(),
      1e-18);
  // Camera components are the plain diagonal blocks; robot rotation moves the target by the
  // lever arm |t(T_target_gripper)| ≈ 1 m, so its translation block is far from zero.
  EXPECT_TRUE((Q[kCameraRotation].topLeftCorner<3, 3>().isIdentity(0.0)));
  EXPECT_GT((Q[kRobotRotation].bottomRightCorner<3, 3>().trace()), 0.1);
}

TEST(WhiteningMatrix, InvertsTheCovarianceAndRejectsSingularOnes) {
  Matrix6d M = Matrix6d::Random();
  const Matrix6d sigma = M * M.transpose() + 0.1 * Matrix6d::Identity();
  const Matrix6d W = WhiteningMatrix(sigma);
  EXPECT_LT((W.transpose() * W - sigma.inverse()).norm(), 1e-9 * sigma.inverse().norm());
  EXPECT_LT((W * sigma * W.transpose() - Matrix6d::Identity()).norm(), 1e-12);
  EXPECT_THROW(WhiteningMatrix(Matrix6d::Zero()), DegenerateError);
  EXPECT_THROW(WhiteningMatrix(PoseCovariance({0.01, 0.0})), DegenerateError);
}

// The closed form of Σ_i equals the sum of its components, both setups, near-identity and
// half-turn poses, with and without the camera's excess variances.
TEST(StationCovarianceOf, EqualsTheCombinedComponents) {
  std::mt19937_64 rng(41);
  hecal::NormalDistribution normal;
  const auto random_pose = [&](double angle) {
    // Drawn last to first: the order these tests' data were generated in.
    const double az = normal(rng), ay = normal(rng), ax = normal(rng);
    const Eigen::Vector3d axis = Eigen::Vector3d(ax, ay, az).normalized();
    const double tz = normal(rng), ty = normal(rng), tx = normal(rng);
    return MakePose(Eigen::AngleAxisd(angle, axis).toRotationMatrix(), Eigen::Vector3d(tx, ty, tz));
  };
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    for (double angle : {1e-9, 0.7, 3.14159}) {
      const Pose A = random_pose(angle), B = random_pose(2.0), X = random_pose(angle);
      for (const NoiseVariances& variances : {NoiseVariances{1e-4, 1e-6, 4e-4, 9e-6, 0.0, 0.0},
                                              NoiseVariances{3e-5, 2e-7, 1e-6, 1e-8, 5e-4, 2e-5}}) {
        const Matrix6d expected =
            CombineComponents(StationNoiseComponents(setup, A, B, X), variances);
        EXPECT_LT((StationCovarianceOf(setup, A, B, X, variances) - expected).norm(),
                  1e-13 * expected.norm())
            << handeye::SetupName(setup) << " angle " << angle;
      }
    }
  }
}

}  // namespace
}  // namespace hecal::estimation
