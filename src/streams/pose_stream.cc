// Time-stamped pose streams: pose_stream.h (docs/streams.md).
#include "hecal/streams/pose_stream.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"

namespace hecal::streams {
namespace {

int LineOf(const PoseStream& stream, size_t k) {
  return k < stream.lines.size() ? stream.lines[k] : 0;
}

std::string Seconds(double t) {
  char text[64];
  std::snprintf(text, sizeof text, "%.9g s", t);
  return text;
}

}  // namespace

void CheckStream(const PoseStream& stream) {
  if (stream.stamps.size() != stream.poses.size()) {
    throw InputError(stream.source, 0,
                     std::to_string(stream.stamps.size()) + " stamps for " +
                         std::to_string(stream.poses.size()) + " poses",
                     "give one stamp per pose");
  }
  if (stream.stamps.size() < 2) {
    throw InputError(stream.source, 0,
                     "a stream needs at least 2 time-stamped samples, this one has " +
                         std::to_string(stream.stamps.size()),
                     "give the whole recording, with a `stamp` column in seconds");
  }
  for (size_t k = 0; k < stream.stamps.size(); ++k) {
    if (!std::isfinite(stream.stamps[k])) {
      throw InputError(stream.source, LineOf(stream, k), "the stamp is not a finite number",
                       "write every stamp as seconds (e.g. 1487321563.68)");
    }
    if (k > 0 && stream.stamps[k] <= stream.stamps[k - 1]) {
      const bool repeated = stream.stamps[k] == stream.stamps[k - 1];
      throw InputError(stream.source, LineOf(stream, k),
                       std::string(repeated ? "the stamp repeats the previous one ("
                                            : "the stamp goes back in time (") +
                           Seconds(stream.stamps[k]) + " after " + Seconds(stream.stamps[k - 1]) +
                           ")",
                       repeated ? "drop the repeated sample" : "sort the stream by its stamps");
    }
  }
}

double MedianPeriod(const PoseStream& stream) {
  std::vector<double> periods;
  for (size_t k = 1; k < stream.stamps.size(); ++k)
    periods.push_back(stream.stamps[k] - stream.stamps[k - 1]);
  if (periods.empty()) return 0.0;
  const auto middle = periods.begin() + static_cast<std::ptrdiff_t>(periods.size() / 2);
  std::nth_element(periods.begin(), middle, periods.end());
  return *middle;
}

std::optional<size_t> Bracket(const PoseStream& stream, double t, double max_gap) {
  const std::vector<double>& s = stream.stamps;
  if (s.size() < 2 || !(t >= s.front()) || !(t <= s.back())) return std::nullopt;
  size_t k = static_cast<size_t>(std::upper_bound(s.begin(), s.end(), t) - s.begin());
  k = std::min(k, s.size() - 1) - 1;
  if (s[k + 1] - s[k] > max_gap) return std::nullopt;
  return k;
}

std::optional<Pose> PoseAt(const PoseStream& stream, double t, double max_gap) {
  const std::optional<size_t> k = Bracket(stream, t, max_gap);
  if (!k) return std::nullopt;
  const Pose& T0 = stream.poses[*k];
  const Pose& T1 = stream.poses[*k + 1];
  const double s = (t - stream.stamps[*k]) / (stream.stamps[*k + 1] - stream.stamps[*k]);
  Pose T = Pose::Identity();
  T.linear() = T0.linear() * so3::Exp(s * so3::Log(T0.linear().transpose() * T1.linear()));
  T.translation() = (1.0 - s) * T0.translation() + s * T1.translation();
  return T;
}

std::optional<Speed> SpeedAt(const PoseStream& stream, double t, double max_gap) {
  const std::optional<size_t> k = Bracket(stream, t, max_gap);
  if (!k) return std::nullopt;
  const Pose& T0 = stream.poses[*k];
  const Pose& T1 = stream.poses[*k + 1];
  const double dt = stream.stamps[*k + 1] - stream.stamps[*k];
  return Speed{.angular = so3::Log(T0.linear().transpose() * T1.linear()).norm() / dt,
               .linear = (T1.translation() - T0.translation()).norm() / dt};
}

}  // namespace hecal::streams
