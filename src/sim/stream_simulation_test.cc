#include "hecal/sim/stream_simulation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "hecal/core/error.h"
#include "hecal/handeye/problem.h"

namespace hecal::sim {
namespace {

TEST(StreamSimulation, StampsRatesAndTheModelAtTheTrueTime) {
  for (const handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    StreamSimulationOptions options;
    options.protocol.setup = setup;
    options.duration = 10.0;
    options.time_offset = 0.137;
    std::mt19937_64 rng(3);
    const SimulatedStreams data = SimulateStreams(options, NoiseModel{}, NoiseModel{}, rng);
    EXPECT_EQ(data.robot_stamps.size(), 501u);
    EXPECT_NEAR(data.robot_stamps[1] - data.robot_stamps[0], 0.02, 1e-12);
    EXPECT_NEAR(data.camera_stamps[1] - data.camera_stamps[0], 1.0 / 30, 1e-12);
    // Camera stamp t is robot time t + offset, inside the robot stream.
    EXPECT_NEAR(data.camera_stamps.front() + data.time_offset, 0.137, 1e-12);
    EXPECT_LE(data.camera_stamps.back() + data.time_offset, 10.0 + 1e-9);
    ASSERT_EQ(data.perfectly_paired.size(), data.camera_stamps.size());
    // Noise-free: Z = A X B with the robot pose at the camera sample's true time.
    const handeye::Problem problem =
        handeye::MakeProblem(setup, data.perfectly_paired, data.T_camera_target);
    for (size_t i = 0; i < problem.A.size(); i += 37) {
      EXPECT_LT(((problem.A[i] * data.X * problem.B[i]).matrix() - data.Z.matrix()).norm(), 1e-9);
    }
    // The robot sample at the same robot time is the same pose (0.137 + k/30 hits a robot stamp
    // only at k = 0 when the offset is a multiple of 0.02; check the first camera sample against
    // the robot stream's own clock instead: stamp 0.14 is robot sample 7).
    EXPECT_LT((data.T_base_gripper[7].matrix() - data.perfectly_paired[0].matrix()).norm(), 0.02);
  }
}

TEST(StreamSimulation, RefusesBadOptions) {
  StreamSimulationOptions options;
  options.camera_rate = 0;
  std::mt19937_64 rng(1);
  EXPECT_THROW(SimulateStreams(options, NoiseModel{}, NoiseModel{}, rng), InputError);
  options = StreamSimulationOptions{};
  options.time_offset = 40.0;  // more than half of 60 s
  EXPECT_THROW(SimulateStreams(options, NoiseModel{}, NoiseModel{}, rng), InputError);
}

}  // namespace
}  // namespace hecal::sim
