// Time-stamped pose streams: pose_stream.h (docs/streams.md).
#include "hecal/streams/pose_stream.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

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

namespace {

// The local regression's equivalent kernel at t: the smoothed value is Σ_j weight_j y_j over the
// samples first, first + 1, …; y_j in the tangent space at sample `nearest`.
struct SmoothingKernel {
  size_t first = 0;
  size_t nearest = 0;
  std::vector<double> weights;
};

std::optional<SmoothingKernel> KernelAt(const PoseStream& stream, double t, double max_gap,
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
  SmoothingKernel kernel{.first = first, .nearest = first, .weights = {}};
  for (size_t j = first; j < end; ++j)
    if (std::abs(s[j] - t) < std::abs(s[kernel.nearest] - t)) kernel.nearest = j;
  // Weighted least squares of y_j = a + b τ_j + c τ_j², τ_j = (t_j − t) / bandwidth: â is
  // Σ_j w_j e₁ᵀ N⁻¹ β_j y_j with N = Σ_j w_j β_j β_jᵀ, β_j = (1, τ_j, τ_j²).
  const auto basis = [&](size_t j) {
    const double tau = (s[j] - t) / bandwidth;
    const double u = 1.0 - std::abs(tau * tau * tau);
    return std::pair<double, Eigen::Vector3d>(u * u * u, Eigen::Vector3d(1.0, tau, tau * tau));
  };
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  for (size_t j = first; j < end; ++j) {
    const auto [weight, beta] = basis(j);
    normal += weight * beta * beta.transpose();
  }
  const Eigen::Vector3d row = normal.ldlt().solve(Eigen::Vector3d::UnitX());
  for (size_t j = first; j < end; ++j) {
    const auto [weight, beta] = basis(j);
    kernel.weights.push_back(weight * row.dot(beta));
  }
  return kernel;
}

}  // namespace

std::optional<Pose> SmoothPoseAt(const PoseStream& stream, double t, double max_gap,
                                 double bandwidth) {
  const std::optional<SmoothingKernel> kernel = KernelAt(stream, t, max_gap, bandwidth);
  if (!kernel) return std::nullopt;
  const Eigen::Matrix3d R_nearest = stream.poses[kernel->nearest].linear();
  Vector6d smoothed = Vector6d::Zero();
  for (size_t i = 0; i < kernel->weights.size(); ++i) {
    const Pose& sample = stream.poses[kernel->first + i];
    Vector6d y;
    y << so3::Log(R_nearest.transpose() * sample.linear()), sample.translation();
    smoothed += kernel->weights[i] * y;
  }
  Pose T = Pose::Identity();
  T.linear() = R_nearest * so3::Exp(smoothed.head<3>());
  T.translation() = smoothed.tail<3>();
  return T;
}

std::optional<double> SmoothingNoiseFactor(const PoseStream& stream, double t, double max_gap,
                                           double bandwidth) {
  const std::optional<SmoothingKernel> kernel = KernelAt(stream, t, max_gap, bandwidth);
  if (!kernel) return std::nullopt;
  double sum = 0.0;
  for (const double weight : kernel->weights) sum += weight * weight;
  return std::sqrt(sum);
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
