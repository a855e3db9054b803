#include "hecal/streams/time_offset_search.h"

#include <gtest/gtest.h>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "hecal/sim/stream_simulation.h"

namespace hecal::streams {
namespace {

PoseStream Stream(const std::vector<double>& stamps, const std::vector<Pose>& poses) {
  return {.stamps = stamps, .poses = poses, .lines = {}, .ids = {}, .source = "camera.csv"};
}

TEST(TimeOffsetSearch, FindsTheOffsetOfBriskMotion) {
  for (const double offset : {-0.15, 0.0, 0.083, 0.4}) {
    sim::StreamSimulationOptions options;
    options.duration = 30;
    options.time_offset = offset;
    options.max_frequency = 0.4;  // speed changes within a second
    std::mt19937_64 rng(11);
    const sim::NoiseModel noise{.kind = sim::NoiseModel::Kind::kGaussian,
                                .rotation_sigma = 0.002,
                                .translation_sigma = 0.0005};
    const sim::SimulatedStreams data = sim::SimulateStreams(options, noise, noise, rng);
    const CoarseOffset found =
        SearchTimeOffset(Stream(data.robot_stamps, data.T_base_gripper),
                         Stream(data.camera_stamps, data.T_camera_target), 1.0, 0.1);
    ASSERT_TRUE(found.found);
    EXPECT_NEAR(found.offset, offset, 0.02) << offset;
    EXPECT_GT(found.correlation, 0.9);
  }
}

TEST(TimeOffsetSearch, StillStreamsHaveNoOffsetAndDisjointOnesAreRefused) {
  PoseStream still;
  still.source = "robot.csv";
  for (int k = 0; k < 200; ++k) {
    still.stamps.push_back(k * 0.02);
    still.poses.push_back(Pose::Identity());
  }
  EXPECT_FALSE(SearchTimeOffset(still, still, 1.0, 0.1).found);
  PoseStream later = still;
  for (double& t : later.stamps) t += 100.0;
  later.source = "camera.csv";
  try {
    SearchTimeOffset(still, later, 1.0, 0.1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "camera.csv");
    EXPECT_NE(std::string(e.what()).find("does not overlap"), std::string::npos);
  }
}

}  // namespace
}  // namespace hecal::streams
