// Stations from two streams: stream_stations.h (docs/streams.md).
#include "hecal/streams/stream_stations.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hecal/streams/time_offset_search.h"

namespace hecal::streams {
namespace {

constexpr double kSelectionSmoothing = 0.5;  // seconds

// The geodesic angle between two rotations.
double Angle(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  const double c = 0.5 * ((A.transpose() * B).trace() - 1.0);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

// Rule 4: farthest-point sampling of at most `keep` of `candidates` by their rotations, none
// within `spacing` seconds of a station kept; time order kept.
std::vector<size_t> Thin(const std::vector<size_t>& candidates, const std::vector<double>& times,
                         const std::vector<Eigen::Matrix3d>& rotations, size_t keep,
                         double spacing) {
  const size_t n = candidates.size();
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<bool> chosen(n, false), excluded(n, false);
  size_t next = 0;
  for (size_t picked = 0; picked < keep && n > 0; ++picked) {
    chosen[next] = true;
    for (size_t k = 0; k < n; ++k)
      if (std::abs(times[k] - times[next]) < spacing) excluded[k] = true;
    size_t farthest = n;
    double best = -1.0;
    for (size_t k = 0; k < n; ++k) {
      if (excluded[k]) continue;
      distance[k] = std::min(distance[k], Angle(rotations[next], rotations[k]));
      if (distance[k] > best) {
        best = distance[k];
        farthest = k;
      }
    }
    if (farthest == n) break;
    next = farthest;
  }
  std::vector<size_t> kept;
  for (size_t k = 0; k < n; ++k)
    if (chosen[k]) kept.push_back(candidates[k]);
  return kept;
}

// Whether every interval of `stream` that meets [a, b] (inside the stream) is at most max_gap long.
bool Covered(const PoseStream& stream, double a, double b, double max_gap) {
  const std::vector<double>& s = stream.stamps;
  const auto first = static_cast<size_t>(std::upper_bound(s.begin(), s.end(), a) - s.begin());
  const auto last = static_cast<size_t>(std::lower_bound(s.begin(), s.end(), b) - s.begin());
  for (size_t j = std::max<size_t>(first, 1); j <= std::min(last, s.size() - 1); ++j)
    if (s[j] - s[j - 1] > max_gap) return false;
  return true;
}

}  // namespace

StreamStations ChooseStations(const PoseStream& robot, const PoseStream& camera, double offset,
                              const StationRules& rules) {
  StreamStations out;
  const double robot_rate = 1.0 / MedianPeriod(robot);
  const double camera_rate = 1.0 / MedianPeriod(camera);
  out.camera_gives_stations = camera_rate <= robot_rate;
  const PoseStream& sparse = out.camera_gives_stations ? camera : robot;
  const PoseStream& dense = out.camera_gives_stations ? robot : camera;
  out.max_gap = rules.max_gap > 0 ? rules.max_gap : 3.0 * MedianPeriod(dense);
  out.smoothing = rules.smoothing > 0 ? rules.smoothing : std::max(0.1, 3.0 * MedianPeriod(dense));
  const double reach = rules.margin + out.smoothing;
  // The denser stream's clock at a sparse sample's time t: robot time t + offset for camera
  // samples, camera time t − offset for robot samples.
  const double sign = out.camera_gives_stations ? 1.0 : -1.0;
  const double robot_gap = std::max(out.max_gap, 3.0 * MedianPeriod(robot));
  out.candidates = static_cast<int>(sparse.stamps.size());
  std::vector<size_t> candidates;
  std::vector<Eigen::Matrix3d> rotations;
  std::vector<double> times;
  for (size_t k = 0; k < sparse.stamps.size(); ++k) {
    const double t = sparse.stamps[k] + sign * offset;
    if (t - reach < dense.stamps.front() || t + reach > dense.stamps.back()) {
      ++out.dropped_outside;
      continue;
    }
    if (!Covered(dense, t - reach, t + reach, out.max_gap)) {
      ++out.dropped_gap;
      continue;
    }
    const double robot_time = out.camera_gives_stations ? t : sparse.stamps[k];
    const std::optional<Speed> speed = SpeedAt(robot, robot_time, robot_gap, kSpeedBaseline);
    if (!speed || speed->angular > rules.max_angular_speed ||
        speed->linear > rules.max_linear_speed) {
      ++out.dropped_fast;
      continue;
    }
    candidates.push_back(k);
    times.push_back(sparse.stamps[k]);
    // Rule 4 picks by rotation: by a rotation smoothed over ±kSelectionSmoothing, so that the
    // choice does not follow the noise of the samples the fit uses (picking the most turned
    // samples would pick those whose noise turns them most).
    const double robot_t = out.camera_gives_stations ? t : sparse.stamps[k];
    const std::optional<Pose> smooth = SmoothPoseAt(robot, robot_t, robot_gap, kSelectionSmoothing);
    const Pose selected = smooth ? *smooth : *PoseAt(robot, robot_t, robot_gap);
    rotations.push_back(selected.linear());
  }
  const auto keep = static_cast<size_t>(std::max(rules.max_stations, 0));
  out.samples = Thin(candidates, times, rotations, keep, 2.0 * out.smoothing);
  out.thinned = static_cast<int>(candidates.size() - out.samples.size());
  return out;
}

namespace {

// The denser stream and the time on its own clock of station sample k (the sparser stream's).
struct DenseTime {
  const PoseStream& stream;
  double t;
};

DenseTime DenseTimeOf(const PoseStream& robot, const PoseStream& camera,
                      const StreamStations& stations, size_t k, double offset) {
  if (stations.camera_gives_stations) return {.stream = robot, .t = camera.stamps[k] + offset};
  return {.stream = camera, .t = robot.stamps[k] - offset};
}

}  // namespace

PairedStreamPoses PosesAt(const PoseStream& robot, const PoseStream& camera,
                          const StreamStations& stations, double offset) {
  PairedStreamPoses out;
  for (const size_t k : stations.samples) {
    const DenseTime dense = DenseTimeOf(robot, camera, stations, k, offset);
    const std::optional<Pose> smoothed =
        SmoothPoseAt(dense.stream, dense.t, stations.max_gap, stations.smoothing);
    if (!smoothed) return {};
    if (stations.camera_gives_stations) {
      out.T_base_gripper.push_back(*smoothed);
      out.T_camera_target.push_back(camera.poses[k]);
      out.camera_stamps.push_back(camera.stamps[k]);
    } else {
      out.T_base_gripper.push_back(robot.poses[k]);
      out.T_camera_target.push_back(*smoothed);
      out.camera_stamps.push_back(dense.t);
    }
  }
  return out;
}

double SmoothedNoiseFactor(const PoseStream& robot, const PoseStream& camera,
                           const StreamStations& stations, double offset) {
  double sum = 0.0;
  int n = 0;
  for (const size_t k : stations.samples) {
    const DenseTime dense = DenseTimeOf(robot, camera, stations, k, offset);
    const std::optional<double> factor =
        SmoothingNoiseFactor(dense.stream, dense.t, stations.max_gap, stations.smoothing);
    if (!factor) continue;
    sum += *factor * *factor;
    ++n;
  }
  return n > 0 ? std::sqrt(sum / n) : 1.0;
}

}  // namespace hecal::streams
