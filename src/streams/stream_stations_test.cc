#include "hecal/streams/stream_stations.h"

#include <gtest/gtest.h>

#include "hecal/geometry/so3.h"

namespace hecal::streams {
namespace {

// A rotation about z at `rate` rad/s, sampled at `hz` from t0 to t1.
PoseStream Turning(double hz, double t0, double t1, double rate) {
  PoseStream stream;
  for (int k = 0; t0 + k / hz <= t1; ++k) {
    const double t = t0 + k / hz;
    stream.stamps.push_back(t);
    stream.poses.push_back(MakePose(so3::Exp(Eigen::Vector3d(0.2 * std::sin(t), 0.1, rate * t)),
                                    Eigen::Vector3d(0.01 * t, 0, 0)));
  }
  return stream;
}

TEST(StreamStations, TheSparserStreamGivesTheStationsAndEachRuleCounts) {
  const PoseStream robot = Turning(50, 0, 20, 0.3);
  PoseStream camera = Turning(30, 1, 19, 0.3);
  StationRules rules;
  rules.smoothing = 0.01;  // spacing 0.02 s: every camera sample may be a station
  rules.max_stations = 100000;
  const StreamStations all = ChooseStations(robot, camera, 0.0, rules);
  EXPECT_TRUE(all.camera_gives_stations);
  EXPECT_EQ(all.candidates, static_cast<int>(camera.stamps.size()));
  EXPECT_EQ(all.samples.size(), camera.stamps.size());
  // The default smoothing of 0.1 s keeps stations 0.2 s apart: about 18 s / 0.2 s of them.
  const StreamStations spaced = ChooseStations(robot, camera, 0.0, StationRules{});
  EXPECT_NEAR(spaced.smoothing, 0.1, 1e-9);
  EXPECT_GT(spaced.samples.size(), 40u);
  EXPECT_LE(spaced.samples.size(), 91u);
  for (size_t i = 1; i < spaced.samples.size(); ++i)
    EXPECT_GE(camera.stamps[spaced.samples[i]] - camera.stamps[spaced.samples[i - 1]], 0.2 - 1e-9);
  EXPECT_NEAR(all.max_gap, 0.06, 1e-9);
  // An offset of 1.5 s puts the camera's last 0.6 s past the robot stream's end.
  const StreamStations shifted = ChooseStations(robot, camera, 1.5, rules);
  EXPECT_GT(shifted.dropped_outside, 15);
  EXPECT_LT(shifted.dropped_outside, 25);
  // A gap of 0.5 s in the robot stream drops the camera samples near it.
  PoseStream gapped = robot;
  for (size_t k = gapped.stamps.size(); k-- > 0;) {
    if (gapped.stamps[k] > 10.0 && gapped.stamps[k] < 10.5) {
      gapped.stamps.erase(gapped.stamps.begin() + static_cast<long>(k));
      gapped.poses.erase(gapped.poses.begin() + static_cast<long>(k));
    }
  }
  EXPECT_GT(ChooseStations(gapped, camera, 0.0, rules).dropped_gap, 15);
  // Faster than the limit: every sample.
  rules.max_angular_speed = 0.2;
  EXPECT_EQ(ChooseStations(robot, camera, 0.0, rules).dropped_fast, all.candidates);
  // Thinning keeps max_stations in time order.
  rules.max_stations = 40;
  rules.max_angular_speed = StationRules{}.max_angular_speed;
  const StreamStations thinned = ChooseStations(robot, camera, 0.0, rules);
  EXPECT_EQ(thinned.samples.size(), 40u);
  EXPECT_EQ(thinned.thinned, all.candidates - 40);
  EXPECT_TRUE(std::is_sorted(thinned.samples.begin(), thinned.samples.end()));
  // The robot as the sparser stream.
  const StreamStations swapped =
      ChooseStations(Turning(20, 0, 20, 0.3), Turning(60, 0, 20, 0.3), 0.0, StationRules{});
  EXPECT_FALSE(swapped.camera_gives_stations);
}

TEST(StreamStations, PosesAtAnOffsetPairEachStationWithTheOtherStream) {
  const PoseStream robot = Turning(50, 0, 20, 0.3);
  const PoseStream camera = Turning(30, 1, 19, 0.3);
  StationRules rules;
  rules.smoothing = 0.05;
  const StreamStations chosen = ChooseStations(robot, camera, 0.0, rules);
  const PairedStreamPoses at = PosesAt(robot, camera, chosen, 0.0);
  ASSERT_EQ(at.T_base_gripper.size(), chosen.samples.size());
  for (size_t i = 0; i < chosen.samples.size(); i += 50) {
    // Same motion in both streams: the smoothed robot pose is the camera's own sample.
    EXPECT_LT((at.T_base_gripper[i].matrix() - at.T_camera_target[i].matrix()).norm(), 1e-4);
    EXPECT_EQ(at.camera_stamps[i], camera.stamps[chosen.samples[i]]);
  }
  // Outside the margin it was chosen for: no poses.
  EXPECT_TRUE(PosesAt(robot, camera, chosen, 5.0).T_base_gripper.empty());
}

}  // namespace
}  // namespace hecal::streams
