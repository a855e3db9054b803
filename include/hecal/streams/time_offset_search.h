// The coarse time offset between a robot stream and a camera stream of one rigid motion
// (docs/streams.md), by correlating their angular speeds — the idea of Furrer, Fehr, Taylor,
// Siegwart and Nieto, "Evaluation of Combined Time-Offset Estimation and Hand-Eye Calibration on
// Robotic Datasets", FSR 2017, §III-A: the gripper and a camera rigidly attached to it (or a
// target it carries, seen by a fixed camera) turn at the same angular speed at every instant,
// whatever X is, so the speed profiles differ only by the clocks' offset.
//
// Convention: a camera sample stamped t was taken at robot-clock time t + offset.
//
// Both angular-speed signals are sampled on one grid of step h = half the smaller median period,
// each from its own stream over a baseline of ±kSpeedBaseline seconds (pose_stream.h's SpeedAt).
// The offset maximises the Pearson correlation of s_camera(t) and s_robot(t + offset) over lags in
// [−window, window] (steps of h), refined by a parabola through the best lag and its neighbours;
// lags whose overlap is under kMinOverlap of the shorter stream's span are skipped. Slow, smooth
// motion makes the peak broad (the speed varies over seconds), so this is only one start of the
// joint fit (time_offset.h), which scans the whole window too.
#pragma once

#include "hecal/streams/pose_stream.h"

namespace hecal::streams {

inline constexpr double kSpeedBaseline = 0.1;  // seconds, each side
inline constexpr double kMinOverlap = 0.5;     // of the shorter stream's span

struct CoarseOffset {
  double offset = 0.0;       // seconds (convention above)
  double correlation = 0.0;  // Pearson correlation at the offset, −1 … 1
  double step = 0.0;         // the grid step h (seconds)
  // False when no lag had enough overlap or the speeds do not vary (a still robot): the offset
  // is then 0 and cannot be told from these streams.
  bool found = false;
};

// max_gap: the interpolation's gap bound (pose_stream.h). Throws hecal::InputError (source the
// camera stream) when the streams do not overlap in time at any lag of the window.
CoarseOffset SearchTimeOffset(const PoseStream& robot, const PoseStream& camera, double window,
                              double max_gap);

}  // namespace hecal::streams
