#include "hecal/handeye/park_martin.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

// Motions whose camera-side rotation axes all lie in one plane: M = Σ β αᵀ has rank 2, where
// (MᵀM)^(−1/2) does not exist; the determinant-corrected polar factor still gives the unique X.
TEST(ParkMartin, CoplanarAxesRankTwoMAreExact) {
  std::mt19937_64 rng(31);
  const Pose X = testing::RandomPose(rng, 0.1);
  const Eigen::Vector3d u = testing::RandomUnitVector(rng);
  const Eigen::Vector3d v = u.cross(testing::RandomUnitVector(rng)).normalized();
  std::vector<Motion> motions;
  for (double phi : {0.0, 0.4, 1.3, 2.2, 3.0}) {
    const Eigen::Vector3d axis = std::cos(phi) * u + std::sin(phi) * v;
    const Pose B = MakePose(so3::Exp((0.5 + phi) * axis), testing::RandomPose(rng).translation());
    motions.push_back({X * B * X.inverse(), B, 0, 1});
  }
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (const Motion& m : motions) M += so3::Log(m.B.linear()) * so3::Log(m.A.linear()).transpose();
  ASSERT_LT(Eigen::JacobiSVD<Eigen::Matrix3d>(M).singularValues()(2), 1e-12);
  testing::ExpectPoseNear(SolveParkMartin(motions), X, 1e-9, "X");
}

// All axes parallel: M has rank 1 and the rotation about the axis is free.
TEST(ParkMartin, ParallelAxesRankOneMThrow) {
  std::mt19937_64 rng(32);
  const Pose X = testing::RandomPose(rng, 0.1);
  const Eigen::Vector3d axis = testing::RandomUnitVector(rng);
  std::vector<Motion> motions;
  for (double angle : {0.5, -1.5, 2.5}) {
    const Pose B = MakePose(so3::Exp(angle * axis), testing::RandomPose(rng).translation());
    motions.push_back({X * B * X.inverse(), B, 0, 1});
  }
  EXPECT_THROW(SolveParkMartin(motions), DegenerateError);
}

// Rotations within 1e-7 rad of π, with the two logarithms taken from quaternions whose signs are
// aligned: β may have |β| > π (the same rotation written with the axis that matches α). Noise of
// 1e-6 rad flips canonical logs at random; the result stays at the noise level.
TEST(ParkMartin, NearHalfTurnMotionsWithTinyNoise) {
  std::mt19937_64 rng(33);
  const Pose X = testing::RandomPose(rng, 0.1);
  hecal::NormalDistribution noise(0.0, 1e-6);
  std::vector<Motion> motions;
  for (int k = 0; k < 12; ++k) {
    // Drawn last to first: the order these tests' data were generated in.
    const Eigen::Vector3d t = testing::RandomPose(rng).translation();
    const Eigen::Vector3d axis = testing::RandomUnitVector(rng);
    const Pose B = MakePose(so3::Exp((std::numbers::pi - 1e-7) * axis), t);
    Pose A = X * B * X.inverse();
    const double dz = noise(rng), dy = noise(rng), dx = noise(rng);
    A.linear() = A.linear() * so3::Exp(Eigen::Vector3d(dx, dy, dz));
    motions.push_back({A, B, 0, 1});
  }
  EXPECT_LT(testing::Error(SolveParkMartin(motions), X).rotation, 1e-5);
}

}  // namespace
}  // namespace hecal::handeye
