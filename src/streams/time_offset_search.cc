// The coarse time offset by angular-speed correlation: time_offset_search.h (docs/streams.md).
#include "hecal/streams/time_offset_search.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "hecal/core/error.h"

namespace hecal::streams {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The angular speed (pose_stream.h) at t = begin + k·h, NaN where the stream has no pose.
std::vector<double> SpeedSignal(const PoseStream& stream, double begin, double h, size_t n,
                                double max_gap) {
  std::vector<double> speed(n, kNaN);
  for (size_t k = 0; k < n; ++k) {
    const std::optional<Speed> at =
        SpeedAt(stream, begin + static_cast<double>(k) * h, max_gap, kSpeedBaseline);
    if (at) speed[k] = at->angular;
  }
  return speed;
}

// The Pearson correlation of camera[k] and robot[k + lag] over the k where both exist; NaN
// with fewer than min_pairs pairs or no variation.
double Correlation(const std::vector<double>& camera, const std::vector<double>& robot,
                   std::ptrdiff_t lag, size_t min_pairs) {
  double n = 0, sc = 0, sr = 0, scc = 0, srr = 0, scr = 0;
  const auto size = static_cast<std::ptrdiff_t>(camera.size());
  for (std::ptrdiff_t k = std::max<std::ptrdiff_t>(0, -lag); k < size && k + lag < size; ++k) {
    const double c = camera[static_cast<size_t>(k)];
    const double r = robot[static_cast<size_t>(k + lag)];
    if (std::isnan(c) || std::isnan(r)) continue;
    n += 1;
    sc += c;
    sr += r;
    scc += c * c;
    srr += r * r;
    scr += c * r;
  }
  if (n < static_cast<double>(min_pairs)) return kNaN;
  const double vc = scc - sc * sc / n;
  const double vr = srr - sr * sr / n;
  if (!(vc > 1e-12 * n) || !(vr > 1e-12 * n)) return kNaN;
  return (scr - sc * sr / n) / std::sqrt(vc * vr);
}

}  // namespace

CoarseOffset SearchTimeOffset(const PoseStream& robot, const PoseStream& camera, double window,
                              double max_gap) {
  // The longest common time of the two streams at any offset of the window: camera time t is
  // robot time t + τ, so the overlap min(r₁, c₁ + τ) − max(r₀, c₀ + τ) is largest at one of these.
  const double r0 = robot.stamps.front(), r1 = robot.stamps.back();
  const double c0 = camera.stamps.front(), c1 = camera.stamps.back();
  double longest = -std::numeric_limits<double>::infinity();
  for (double tau : {-window, window, r0 - c0, r1 - c1}) {
    tau = std::clamp(tau, -window, window);
    longest = std::max(longest, std::min(r1, c1 + tau) - std::max(r0, c0 + tau));
  }
  if (!(longest > 0)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "the camera stream (%.3f … %.3f s) does not overlap the robot stream "
                  "(%.3f … %.3f s) at any offset within ±%g s",
                  c0, c1, r0, r1, window);
    throw InputError(camera.source, 0, text,
                     "give streams of the same recording with stamps in seconds, or widen "
                     "--time-offset-window");
  }
  CoarseOffset out;
  const double h = 0.5 * std::min(MedianPeriod(robot), MedianPeriod(camera));
  out.step = h;
  const double begin = std::min(robot.stamps.front(), camera.stamps.front());
  const double end = std::max(robot.stamps.back(), camera.stamps.back());
  const size_t n = static_cast<size_t>((end - begin) / h) + 1;
  const std::vector<double> robot_speed = SpeedSignal(robot, begin, h, n, max_gap);
  const std::vector<double> camera_speed = SpeedSignal(camera, begin, h, n, max_gap);
  const double shorter = std::min(robot.stamps.back() - robot.stamps.front(),
                                  camera.stamps.back() - camera.stamps.front());
  const auto min_pairs = static_cast<size_t>(std::max(3.0, kMinOverlap * shorter / h));
  const auto lags = static_cast<std::ptrdiff_t>(std::floor(window / h));
  std::vector<double> correlation(static_cast<size_t>(2 * lags + 1), kNaN);
  bool overlap = false;
  std::ptrdiff_t best = 0;
  for (std::ptrdiff_t lag = -lags; lag <= lags; ++lag) {
    const double c = Correlation(camera_speed, robot_speed, lag, min_pairs);
    correlation[static_cast<size_t>(lag + lags)] = c;
    if (std::isnan(c)) continue;
    if (!overlap || c > correlation[static_cast<size_t>(best + lags)]) best = lag;
    overlap = true;
  }
  if (!overlap) return out;  // no motion to correlate
  double offset = static_cast<double>(best) * h;
  const size_t at = static_cast<size_t>(best + lags);
  if (at > 0 && at + 1 < correlation.size() && !std::isnan(correlation[at - 1]) &&
      !std::isnan(correlation[at + 1])) {
    const double a = correlation[at - 1], b = correlation[at], c = correlation[at + 1];
    const double curvature = a - 2 * b + c;
    if (curvature < 0) offset += h * 0.5 * (a - c) / curvature;
  }
  out.offset = offset;
  out.correlation = correlation[at];
  out.found = true;
  return out;
}

}  // namespace hecal::streams
