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

std::optional<Pose> SmoothPoseAt(const PoseStream& stream, double t, double max_gap,
                                 double bandwidth) {
  const std::vector<double>& s = stream.stamps;
  const auto first =
      static_cast<size_t>(std::upper_bound(s.begin(), s.end(), t - bandwidth) - s.begin());
  const auto end =
      static_cast<size_t>(std::lower_bound(s.begin(), s.end(), t + bandwidth) - s.begin());
  int before = 0, after = 0;
  for (size_t j = first; j < end; ++j) {
    if (j > first && s[j] - s[j - 1] > max_gap) return std::nullopt;
    (s[j] <= t ? before : after) += 1;
  }
  if (before < 2 || after < 2) return std::nullopt;
  size_t nearest = first;
  for (size_t j = first; j < end; ++j)
    if (std::abs(s[j] - t) < std::abs(s[nearest] - t)) nearest = j;
  const Eigen::Matrix3d R_nearest = stream.poses[nearest].linear();
  // Weighted least squares of y_j = a + b τ_j + c τ_j², τ_j = (t_j − t) / bandwidth.
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 6> right = Eigen::Matrix<double, 3, 6>::Zero();
  for (size_t j = first; j < end; ++j) {
    const double tau = (s[j] - t) / bandwidth;
    const double u = 1.0 - std::abs(tau * tau * tau);
    const double weight = u * u * u;
    const Eigen::Vector3d basis(1.0, tau, tau * tau);
    Vector6d y;
    y << so3::Log(R_nearest.transpose() * stream.poses[j].linear()), stream.poses[j].translation();
    normal += weight * basis * basis.transpose();
    right += weight * basis * y.transpose();
  }
  const Eigen::Matrix<double, 3, 6> coefficients = normal.ldlt().solve(right);
  Pose T = Pose::Identity();
  T.linear() = R_nearest * so3::Exp(coefficients.row(0).head<3>().transpose());
  T.translation() = coefficients.row(0).tail<3>().transpose();
  return T;
}

std::optional<Speed> SpeedAt(const PoseStream& stream, double t, double max_gap, double baseline) {
  const std::optional<Pose> before = PoseAt(stream, t - baseline, max_gap);
  const std::optional<Pose> after = PoseAt(stream, t + baseline, max_gap);
  if (!before || !after) return std::nullopt;
  return Speed{
      .angular = so3::Log(before->linear().transpose() * after->linear()).norm() / (2 * baseline),
      .linear = (after->translation() - before->translation()).norm() / (2 * baseline)};
}

}  // namespace hecal::streams
