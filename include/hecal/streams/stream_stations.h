// Stations from two time-stamped streams (docs/streams.md): which samples become stations and
// their paired poses at a time offset.
//
// The sparser stream (fewer samples per second) gives the stations: each of its samples is a
// candidate, and the denser stream's smoothed pose is taken at that sample's time on its own clock
// (pose_stream.h's SmoothPoseAt over ±smoothing; convention of time_offset_search.h: camera time
// t is robot time t + offset).
// The rule, in this order, each drop counted:
//   1. outside: the denser stream does not cover the sample's time ± smoothing at every offset
//      within ±margin of the offset (the fit moves the offset that far);
//   2. gap: two samples in that span are more than max_gap apart (never smoothed across;
//      default 3 × the denser stream's median period);
//   3. fast: the robot moves faster than max_angular_speed or max_linear_speed there (the robot
//      stream's speed over ±kSpeedBaseline, pose_stream.h, time_offset_search.h): motion blur in
//      the image and interpolation error grow with speed (defaults 45°/s and 0.3 m/s: at 30 Hz and
//      10 ms exposure, 0.45° and 3 mm of blur);
//   4. thinned: farthest-point sampling in rotation keeps at most max_stations well spread ones,
//      no two closer in time than twice the smoothing — starting from the first candidate, each
//      next station is the candidate, not within that time of a station kept, whose robot
//      rotation is farthest (geodesic angle) from every station kept. The rotation spread favours
//      the large rotations between stations that hand–eye calibration needs (Tsai and Lenz 1989,
//      §V); the spacing keeps the stations' smoothed poses from sharing samples, so their noise
//      is independent as the fit assumes (sharing made the offset's σ 3× too small). The kept
//      stations stay in time order.
#pragma once

#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/streams/pose_stream.h"

namespace hecal::streams {

struct StationRules {
  double max_gap = 0.0;                           // seconds; 0: 3 × the denser's period
  double max_angular_speed = 0.7853981633974483;  // rad/s (45°/s)
  double max_linear_speed = 0.3;                  // m/s
  int max_stations = 500;
  double margin = 0.0;     // seconds, rule 1
  double smoothing = 0.0;  // seconds; 0: max(0.1 s, 3 periods of the denser stream)
};

struct StreamStations {
  bool camera_gives_stations = true;  // false: the robot stream is the sparser one
  double max_gap = 0.0;               // the bound used (seconds)
  double smoothing = 0.0;             // the smoothing half-width used (seconds)
  std::vector<size_t> samples;        // the stations: indices into the sparser stream, in order
  int candidates = 0;                 // samples of the sparser stream
  int dropped_outside = 0;
  int dropped_gap = 0;
  int dropped_fast = 0;
  int thinned = 0;
};

// Rules 1–4 at `offset`.
StreamStations ChooseStations(const PoseStream& robot, const PoseStream& camera, double offset,
                              const StationRules& rules);

struct PairedStreamPoses {
  std::vector<Pose> T_base_gripper;
  std::vector<Pose> T_camera_target;
  std::vector<double> camera_stamps;  // each station's time on the camera clock
};

// The stations' poses at `offset`: each station's own sample and the denser stream's smoothed pose
// at its time. A station whose smoothed pose is missing at this offset (outside ±margin of the
// offset it was chosen at) makes the result empty.
PairedStreamPoses PosesAt(const PoseStream& robot, const PoseStream& camera,
                          const StreamStations& stations, double offset);

// The denser stream's noise at the stations over its noise per sample: the RMS over the stations
// of pose_stream.h's SmoothingNoiseFactor at `offset` (1 when it has no station there).
double SmoothedNoiseFactor(const PoseStream& robot, const PoseStream& camera,
                           const StreamStations& stations, double offset);

}  // namespace hecal::streams
