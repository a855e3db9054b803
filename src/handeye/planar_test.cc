#include "hecal/handeye/planar.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/se3.h"
#include "hecal/handeye/observability.h"
#include "hecal/sim/planar_robot.h"
#include "testing/thrown.h"

namespace hecal::handeye {
namespace {

sim::PlanarScene NoiseFree(Setup setup, uint64_t seed) {
  std::mt19937_64 rng(seed);
  return sim::DrawPlanarScene(setup, 12, {}, {}, rng);
}

// max_i |Log(Z⁻¹ A_i X B_i)|: zero for an exact solution of noise-free data.
double LoopError(const Problem& problem, const Solution& solution) {
  double worst = 0.0;
  for (size_t i = 0; i < problem.A.size(); ++i) {
    const Pose E = solution.Z.inverse() * problem.A[i] * solution.X * problem.B[i];
    worst = std::max(worst, se3::Log(E).norm());
  }
  return worst;
}

TEST(Planar, ParallelAxesNameTheComponentAndTheFlag) {
  for (handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    const sim::PlanarScene scene = NoiseFree(setup, 1);
    const DegenerateError error =
        testing::Thrown<DegenerateError>([&] { CheckObservability(scene.truth); });
    EXPECT_NE(std::string(error.what()).find("--fix tz=VALUE"), std::string::npos) << error.what();
    EXPECT_NO_THROW(CheckObservability(scene.truth, /*translation_fixed=*/true));
  }
}

TEST(Planar, TheLeastObservedDirectionIsTheRotationAxis) {
  // Eye-in-hand the axis is the gripper's z; eye-to-hand the base's z (planar_robot.h).
  for (handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    const Eigen::Vector3d d = LeastObservedTranslation(NoiseFree(setup, 2).truth);
    EXPECT_NEAR(std::abs(d.z()), 1.0, 1e-9);
    EXPECT_GT(d.z(), 0.0);  // its largest coordinate positive
    EXPECT_EQ(NearestAxis(d), 2);
  }
}

TEST(Planar, TheFamilyFitsNoiseFreeDataEqually) {
  for (handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    const sim::PlanarScene scene = NoiseFree(setup, 3);
    const FixedTranslation fixed = ResolveFix(scene.truth, {2, scene.X.translation().z() + 0.25});
    const Solution moved = ApplyFix({scene.X, scene.Z}, fixed);
    EXPECT_NEAR(moved.X.translation().z(), scene.X.translation().z() + 0.25, 1e-12);
    EXPECT_LT(LoopError(scene.truth, moved), 1e-9);
  }
}

TEST(Planar, FixedStartRecoversNoiseFreeTruth) {
  for (handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    const sim::PlanarScene scene = NoiseFree(setup, 4);
    const FixedTranslation fixed = ResolveFix(scene.truth, {2, scene.X.translation().z()});
    const Solution start = FixedStart(scene.truth, fixed);
    EXPECT_LT(se3::Log(scene.X.inverse() * start.X).norm(), 1e-8) << SetupName(setup);
    EXPECT_LT(se3::Log(scene.Z.inverse() * start.Z).norm(), 1e-8) << SetupName(setup);
  }
}

TEST(Planar, AComponentAcrossTheAxisIsRefusedNamingTheOneToFix) {
  const sim::PlanarScene scene = NoiseFree(Setup::kEyeInHand, 5);
  const InputError error = testing::Thrown<InputError>([&] { ResolveFix(scene.truth, {0, 0.1}); });
  EXPECT_NE(std::string(error.what()).find("fix tz instead"), std::string::npos) << error.what();
}

TEST(Planar, TheConstrainedInverseHasNoVarianceAlongTheFixedCoordinate) {
  const sim::PlanarScene scene = NoiseFree(Setup::kEyeInHand, 6);
  const FixedTranslation fixed = ResolveFix(scene.truth, {2, 0.06});
  const Solution at = ApplyFix({scene.X, scene.Z}, fixed);
  std::mt19937_64 rng(7);
  hecal::NormalDistribution normal;
  Eigen::Matrix<double, 12, 12> J;
  for (double& v : J.reshaped()) v = normal(rng);
  const Eigen::Matrix<double, 12, 12> H = J.transpose() * J;
  const Eigen::Matrix<double, 12, 12> covariance = ConstrainedInverse(H, at, fixed);
  const Eigen::Matrix<double, 12, 1> c = FixGradient(at, fixed);
  EXPECT_LT(std::abs(c.dot(covariance * c)), 1e-12);
  // On the tangent it inverts H: U ᵀ H Σ H U = Uᵀ H U.
  const Eigen::Matrix<double, 12, 11> U = FixTangentBasis(at, fixed);
  EXPECT_LT((U.transpose() * H * covariance * H * U - U.transpose() * H * U).norm(),
            1e-9 * H.norm());
  EXPECT_LT((U.transpose() * c).norm(), 1e-14);
}

}  // namespace
}  // namespace hecal::handeye
