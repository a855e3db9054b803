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
// Smoothed pose at a time (the stations' poses of the denser stream, stream_stations.h): a local
// quadratic regression (LOESS, Cleveland 1979) of the samples within ±b of t, tricube weights
// (1 − |τ/b|³)³, in the tangent space at the sample nearest t (rotation Log(R_nᵀ R_j), position
// p_j), evaluated at t. Why not the geodesic between the two nearest samples: its noise is the two
// samples' noise weighted by (1 − s) and s, so its variance (1 − s)² + s² swings between ½ and 1
// each sample period, and a fit of the time offset over noisy streams is drawn to the offsets
// where the swing is lowest (measured: 10 ms of bias at the thesis' 1 mm / 1° noise, 30 Hz camera,
// 50 Hz robot). The regression's weights move smoothly with t, its noise is nearly constant, and
// it reproduces any motion quadratic in t exactly; its error on smooth motion grows as b³ times
// the third derivative (below 1e-5 rad at b = 0.1 s for the motions of sim/stream_simulation.h).
// nullopt without 2 samples on each side within b, or across a gap longer than max_gap.
//
// Speed at a time t over a baseline b: of the poses at t − b and t + b (interpolated), the angular
// speed |Log(R₋ᵀ R₊)| / 2b (rad/s; the same in every frame rigidly attached to the moving body)
// and the linear speed |p₊ − p₋| / 2b of the pose's origin (m/s). The baseline averages the
// finite difference's noise: at 30 Hz and 1° of noise per pose, consecutive samples would give
// ~80°/s of noise, a baseline of 0.1 s ~12°/s.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"

namespace hecal::streams {

struct PoseStream {
  std::vector<double> stamps;    // seconds, strictly increasing
  std::vector<Pose> poses;       // one per stamp, metres
  std::vector<int> lines;        // each sample's 1-based line in its file (empty: none)
  std::vector<std::string> ids;  // each sample's id (empty: none)
  std::string source;            // the file's name, for messages
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

// The smoothed pose at time t (as above) over ±bandwidth seconds.
std::optional<Pose> SmoothPoseAt(const PoseStream& stream, double t, double max_gap,
                                 double bandwidth);

// The smoothed pose's noise over one sample's, for independent noise of one spread on every
// sample: √(Σ_j ℓ_j²), ℓ_j the regression's weight of sample j in the pose at t (the smoothed
// pose is Σ_j ℓ_j y_j in the tangent space). About 0.5 for the 10 samples of ±0.1 s at 50 Hz;
// nullopt where SmoothPoseAt gives no pose.
std::optional<double> SmoothingNoiseFactor(const PoseStream& stream, double t, double max_gap,
                                           double bandwidth);

struct Speed {
  double angular = 0.0;  // rad/s
  double linear = 0.0;   // m/s
};
// The speed at time t over `baseline` seconds each side (as above), nullopt when a pose is
// missing (outside the stream or across a gap).
std::optional<Speed> SpeedAt(const PoseStream& stream, double t, double max_gap, double baseline);

}  // namespace hecal::streams
