// A time-stamped pose stream (docs/streams.md): a robot controller's T_base_gripper log or a
// camera's / tracker's T_camera_target track, each sample with its stamp in seconds on the
// recorder's own clock.
//
// Interpolation: the pose at a time between two samples is the geodesic of SO(3) × R³ between
// them — the rotation by slerp, the translation linearly:
//     R(t) = R₀ · Exp(s · Log(R₀ᵀ R₁)),   p(t) = (1 − s) p₀ + s p₁,   s = (t − t₀) / (t₁ − t₀).
// Chosen over the screw geodesic of SE(3) (se3::Interpolate) because it is how controllers
// interpolate a linear move (position along a line, orientation by slerp), so between two samples
// of a controller's log it is the exact path; the two differ by O(|ω| |Δp| Δt²) anyway, far below
// the noise at 30 Hz and more. A sample is never made across a gap: when the two samples around t
// are more than `max_gap` seconds apart there is no pose at t (it is dropped and counted).
//
// Speed at a time: of the same two samples, the angular speed |Log(R₀ᵀ R₁)| / Δt (rad/s; the
// same in every frame rigidly attached to the moving body) and the linear speed |p₁ − p₀| / Δt of
// the pose's origin (m/s).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"

namespace hecal::streams {

struct PoseStream {
  std::vector<double> stamps;  // seconds, strictly increasing
  std::vector<Pose> poses;     // one per stamp, metres
  std::vector<int> lines;      // each sample's 1-based line in its file (empty: none)
  std::string source;          // the file's name, for messages
};

// Throws hecal::InputError naming the source and the sample's line when the stream has fewer
// than 2 samples, stamps and poses differ in number, a stamp is not finite, or stamps are not
// strictly increasing (a duplicate or a step back: sort the file, or drop the repeated row).
void CheckStream(const PoseStream& stream);

// The median spacing of the stamps (seconds).
double MedianPeriod(const PoseStream& stream);

// The index k with stamps[k] <= t < stamps[k + 1] when both exist and are at most max_gap apart
// (t equal to the last stamp gives the last interval); nullopt otherwise.
std::optional<size_t> Bracket(const PoseStream& stream, double t, double max_gap);

// The pose at time t (interpolated as above), nullopt outside the stream or across a gap.
std::optional<Pose> PoseAt(const PoseStream& stream, double t, double max_gap);

struct Speed {
  double angular = 0.0;  // rad/s
  double linear = 0.0;   // m/s
};
// The speed at time t (as above), nullopt outside the stream or across a gap.
std::optional<Speed> SpeedAt(const PoseStream& stream, double t, double max_gap);

}  // namespace hecal::streams
