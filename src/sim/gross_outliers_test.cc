#include "hecal/sim/gross_outliers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hecal/geometry/so3.h"

namespace hecal::sim {
namespace {

SimulatedData Data(int stations, std::mt19937_64& rng) {
  ProtocolOptions options;
  options.stations = stations;
  return SimulateThesisProtocol(options, {}, {}, rng);
}

// k distinct stations, ascending; only their robot poses change; the others are untouched.
TEST(GrossOutliers, ReplacesTheRobotPoseOfDistinctStations) {
  std::mt19937_64 rng(7);
  const SimulatedData clean = Data(20, rng);
  for (int k : {0, 1, 4, 20}) {
    SimulatedData data = clean;
    const std::vector<int> replaced = InjectGrossOutliers(&data, k, rng);
    ASSERT_EQ(replaced.size(), static_cast<size_t>(k));
    EXPECT_TRUE(std::is_sorted(replaced.begin(), replaced.end()));
    EXPECT_TRUE(std::adjacent_find(replaced.begin(), replaced.end()) == replaced.end());
    for (int i = 0; i < 20; ++i) {
      const bool is_replaced = std::find(replaced.begin(), replaced.end(), i) != replaced.end();
      EXPECT_EQ(data.T_base_gripper[i].isApprox(clean.T_base_gripper[i], 1e-12), !is_replaced);
      EXPECT_TRUE(data.T_camera_target[i].isApprox(clean.T_camera_target[i], 0.0));
      EXPECT_LT(so3::OrthonormalityError(data.T_base_gripper[i].linear()), 1e-12);
      EXPECT_LE(data.T_base_gripper[i].translation().cwiseAbs().maxCoeff(),
                is_replaced ? 1.0 : 1e9);
    }
  }
  SimulatedData data = clean;
  EXPECT_THROW(InjectGrossOutliers(&data, 21, rng), std::invalid_argument);
}

// Uniform rotations have E[trace R] = 0 and Var(trace R) = 1 (trace = 1 + 2 cos θ, θ with density
// (1 − cos θ)/π), and translations uniform in the cube have mean 0 and variance 1/3 per axis.
TEST(GrossOutliers, RotationsAreUniformAndTranslationsInTheCube) {
  std::mt19937_64 rng(11);
  SimulatedData data = Data(4000, rng);
  InjectGrossOutliers(&data, 4000, rng);
  double trace = 0.0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Pose& T : data.T_base_gripper) {
    trace += T.linear().trace();
    mean += T.translation();
  }
  trace /= 4000.0;
  mean /= 4000.0;
  // Var(trace R) = 1 for uniform rotations: the mean of 4000 is within 4/sqrt(4000) of 0.
  EXPECT_NEAR(trace, 0.0, 4.0 / std::sqrt(4000.0));
  EXPECT_LT(mean.cwiseAbs().maxCoeff(), 4.0 * std::sqrt(1.0 / 3.0 / 4000.0));
}

}  // namespace
}  // namespace hecal::sim
