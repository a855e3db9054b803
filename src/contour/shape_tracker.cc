// The shape-space Kalman filter: see shape_tracker.h.
#include "hecal/contour/shape_tracker.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"

namespace hecal::contour {
namespace {

// A positive finite value of `field`, or Invalid.
bool PositiveValid(double value, const char* field, const char* fix, std::string* why) {
  if (value > 0.0 && std::isfinite(value)) return true;
  return Invalid(why, field, "must be a finite number above 0", fix);
}

// The options, once IsValid (for the constructor's initialiser list).
const ShapeTrackerOptions& Validated(const ShapeTrackerOptions& options) {
  RequireValid(options);
  return options;
}

}  // namespace

bool ShapeTrackerOptions::IsValid(std::string* why) const {
  if (ShapeSubspaceName(subspace) == "?") {
    return Invalid(why, "ShapeTrackerOptions.subspace", "is not a shape subspace",
                   "give one of the ShapeSubspace values (shape_space.h)");
  }
  if (points_per_span < 1 || points_per_span > 1000) {
    return Invalid(why, "ShapeTrackerOptions.points_per_span",
                   "must be 1 … 1000, got " + std::to_string(points_per_span),
                   "sample the curve at a few points per span (default 8)");
  }
  if (!search.IsValid(why)) return false;
  if (iterations < 1 || iterations > 100) {
    return Invalid(why, "ShapeTrackerOptions.iterations",
                   "must be 1 … 100, got " + std::to_string(iterations),
                   "use a few passes per frame (default 4)");
  }
  return PositiveValid(gate, "ShapeTrackerOptions.gate",
                       "give the gate in standard deviations (default 3)", why) &&
         (!measurement_sigma ||
          PositiveValid(*measurement_sigma, "ShapeTrackerOptions.measurement_sigma",
                        "give σ in pixels, or leave it to be estimated", why)) &&
         PositiveValid(sigma_floor, "ShapeTrackerOptions.sigma_floor",
                       "give the floor in pixels (default 0.02)", why) &&
         PositiveValid(initial_measurement_sigma, "ShapeTrackerOptions.initial_measurement_sigma",
                       "give it in pixels (default 1)", why) &&
         PositiveValid(process_noise, "ShapeTrackerOptions.process_noise",
                       "give it in px per frame² (default 1)", why) &&
         PositiveValid(initial_sigma, "ShapeTrackerOptions.initial_sigma",
                       "give it in pixels (default 2)", why) &&
         PositiveValid(initial_velocity_sigma, "ShapeTrackerOptions.initial_velocity_sigma",
                       "give it in px per frame (default 5)", why) &&
         (min_edges >= 0 || Invalid(why, "ShapeTrackerOptions.min_edges",
                                    "must be 0 or more, got " + std::to_string(min_edges),
                                    "give 0 for the default max(3k, 12)"));
}

namespace {

Eigen::MatrixXd Symmetrise(const Eigen::MatrixXd& m) {
  return 0.5 * (m + m.transpose());
}

}  // namespace

// One pass of the measurement process: the rows h_j and values y_j of the used edges.
struct ShapeTracker::Pass {
  Eigen::MatrixXd H;  // m × k
  Eigen::VectorXd y;  // m
  int searched = 0;
  int found = 0;
  int positive = 0;  // used edges with a positive gradient
  int used() const { return static_cast<int>(y.size()); }
};

ShapeTracker::ShapeTracker(const Eigen::Matrix2Xd& control_points, const Eigen::Vector2d& origin,
                           const ShapeTrackerOptions& options)
    : options_(options),
      search_(options.search),
      origin_(origin),
      space_((Validated(options), control_points.colwise() - origin), options.subspace) {
  if (!origin.allFinite()) {
    throw InputError("contour tracker", 0, "the origin (principal point) is not finite",
                     "give finite pixel coordinates");
  }
  const int k = space_.dim();
  const double n = static_cast<double>(control_points.cols());
  unit_shape_covariance_ = (2.0 * n / k) * space_.FitCovariance(1.0);
  state_ = Eigen::VectorXd::Zero(2 * k);
  covariance_ = Eigen::MatrixXd::Zero(2 * k, 2 * k);
  covariance_.topLeftCorner(k, k) =
      options.initial_sigma * options.initial_sigma * unit_shape_covariance_;
  covariance_.bottomRightCorner(k, k) =
      options.initial_velocity_sigma * options.initial_velocity_sigma * unit_shape_covariance_;
  sigma_ = options.measurement_sigma.value_or(options.initial_measurement_sigma);
}

ClosedBSpline ShapeTracker::Curve(const Eigen::VectorXd& x) const {
  return ClosedBSpline(space_.Apply(x).colwise() + origin_);
}

ShapeTracker::Pass ShapeTracker::Measure(const GrayImage& image, const Eigen::VectorXd& x,
                                         const Eigen::MatrixXd& cov, double sigma) const {
  const ClosedBSpline curve = Curve(x);
  const Eigen::VectorXd parameters = curve.SampleParameters(options_.points_per_span);
  const Eigen::Index n = space_.template_points().cols();
  const Eigen::MatrixXd& W = space_.W();
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<double> values;
  Pass pass;
  for (Eigen::Index j = 0; j < parameters.size(); ++j) {
    const double s = parameters(j);
    const Eigen::Vector2d normal = curve.Normal(s);
    if (normal.isZero()) continue;  // a cusp (a corner of tripled control points): no normal
    ++pass.searched;
    const std::optional<EdgeHit> hit = SearchEdge(image, curve.Point(s), normal, search_);
    if (!hit) continue;
    ++pass.found;
    const Eigen::RowVectorXd b = curve.Basis(s);
    const Eigen::RowVectorXd h =
        normal.x() * (b * W.topRows(n)) + normal.y() * (b * W.bottomRows(n));
    const double spread = std::sqrt((h * cov * h.transpose())(0, 0) + sigma * sigma);
    if (std::abs(hit->offset) > options_.gate * spread) continue;
    rows.push_back(h);
    values.push_back((h * x)(0) + hit->offset);
    if (hit->gradient > 0.0) ++pass.positive;
  }
  pass.H.resize(static_cast<Eigen::Index>(rows.size()), space_.dim());
  pass.y.resize(static_cast<Eigen::Index>(values.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    pass.H.row(static_cast<Eigen::Index>(i)) = rows[i];
    pass.y(static_cast<Eigen::Index>(i)) = values[i];
  }
  return pass;
}

TrackedFrame ShapeTracker::Track(const GrayImage& image) {
  const int k = space_.dim();
  const int n = static_cast<int>(state_.size());  // 2k, or 3k with the template error
  if (frames_ > 0) {  // predict: x' = x + v, v' = v (+ the random acceleration), e' = e
    Eigen::MatrixXd F = Eigen::MatrixXd::Identity(n, n);
    F.block(0, k, k, k).setIdentity();
    const Eigen::MatrixXd C =
        options_.process_noise * options_.process_noise * unit_shape_covariance_;
    Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(n, n);
    Q.topLeftCorner(2 * k, 2 * k) << C / 3.0, C / 2.0, C / 2.0, C;
    state_ = F * state_;
    covariance_ = Symmetrise(F * covariance_ * F.transpose() + Q);
  }
  const int min_edges = options_.min_edges > 0 ? options_.min_edges : std::max(3 * k, 12);
  const Eigen::VectorXd prior_state = state_;
  const Eigen::MatrixXd prior_covariance = covariance_;

  TrackedFrame frame;
  frame.frame = frames_;
  double sigma = options_.measurement_sigma.value_or(sigma_);
  Eigen::VectorXd estimate = prior_state;
  Eigen::MatrixXd estimate_covariance = prior_covariance;
  Pass last;
  // The update of shape_tracker.h relative to the prior, computed without inverting P⁻ (which is
  // singular right after the template is refined): with A = Σ h hᵀ/σ², b = Σ hᵀ(y − h x⁻)/σ²
  // and P⁻_{·x} the columns of P⁻ for x, the push-through identity gives
  //   X⁺ = X⁻ + P⁻_{·x} (I + A P⁻_xx)⁻¹ b,   P⁺ = P⁻ − P⁻_{·x} (I + A P⁻_xx)⁻¹ A P⁻_{x·},
  // which equals (P⁻⁻¹ + Hᵀ H/σ²)⁻¹ and its mean whenever P⁻ is invertible.
  const auto solve = [&](const Pass& pass, double s) {
    const Eigen::MatrixXd A = pass.H.transpose() * pass.H / (s * s);
    const Eigen::VectorXd b =
        pass.H.transpose() * (pass.y - pass.H * prior_state.head(k)) / (s * s);
    const Eigen::MatrixXd Pcx = prior_covariance.leftCols(k);
    const Eigen::MatrixXd G =
        (Eigen::MatrixXd::Identity(k, k) + A * prior_covariance.topLeftCorner(k, k))
            .partialPivLu()
            .inverse();
    estimate = prior_state + Pcx * (G * b);
    estimate_covariance = Symmetrise(prior_covariance - Pcx * G * A * Pcx.transpose());
  };
  const auto residual_sum = [&](const Pass& pass) {
    return (pass.y - pass.H * estimate.head(k)).squaredNorm();
  };
  for (int iteration = 0; iteration < options_.iterations; ++iteration) {
    Pass pass = Measure(image, estimate.head(k), estimate_covariance.topLeftCorner(k, k), sigma);
    frame.edges_searched = pass.searched;
    frame.edges_found = pass.found;
    frame.edges_used = pass.used();
    if (pass.used() < min_edges) break;
    solve(pass, sigma);
    if (!options_.measurement_sigma) {
      const int dof = std::max(1, pass.used() - k);
      sigma = std::max(options_.sigma_floor, std::sqrt(residual_sum(pass) / dof));
      solve(pass, sigma);
    }
    frame.updated = true;
    last = std::move(pass);
  }
  if (frame.updated) {
    state_ = estimate;
    covariance_ = estimate_covariance;
    frame.residual_rms = std::sqrt(residual_sum(last) / std::max(1, last.used()));
    frame.edges_used = last.used();
    sigma_ = sigma;
  }
  frame.sigma = sigma;
  frame.sigma_estimated = !options_.measurement_sigma.has_value();

  if (frames_ == 0 && frame.updated) {
    if (options_.learn_polarity && search_.polarity == 0 && last.used() > 0) {
      const int used = last.used();
      if (last.positive >= 0.9 * used) search_.polarity = +1;
      if (used - last.positive >= 0.9 * used) search_.polarity = -1;
    }
    if (options_.refine_template) {
      // The fitted contour becomes the template (x = 0). Its fit error e0 is kept as a constant
      // state e: the true x is then S − e0, so the errors of x and e start as (e0, −e0) and the
      // motion since the first view is S = x + e (shape_tracker.h). To first order the reduced
      // coordinates of the old and new templates coincide.
      template_shape_ = space_.Shape(state_.head(k));
      space_ = ShapeSpace(space_.Apply(state_.head(k)), options_.subspace);
      unit_shape_covariance_ = (2.0 * static_cast<double>(space_.template_points().cols()) / k) *
                               space_.FitCovariance(1.0);
      Eigen::MatrixXd T = Eigen::MatrixXd::Zero(3 * k, 2 * k);
      T.topLeftCorner(2 * k, 2 * k).setIdentity();
      T.bottomLeftCorner(k, k) = -Eigen::MatrixXd::Identity(k, k);
      covariance_ = Symmetrise(T * covariance_ * T.transpose());
      const Eigen::VectorXd velocity = state_.segment(k, k);
      state_ = Eigen::VectorXd::Zero(3 * k);
      state_.segment(k, k) = velocity;
    }
  }
  frame.x = state_.head(k);
  frame.x_covariance = covariance_.topLeftCorner(k, k);
  frame.velocity = state_.segment(k, k);
  // The motion since the first view: x (+ e with a refined template).
  Eigen::MatrixXd motion = Eigen::MatrixXd::Zero(k, state_.size());
  motion.leftCols(k).setIdentity();
  if (state_.size() == 3 * k) motion.rightCols(k).setIdentity();
  const Eigen::VectorXd m = motion * state_;
  frame.shape = space_.Shape(m);
  frame.shape_covariance =
      space_.basis() * (motion * covariance_ * motion.transpose()) * space_.basis().transpose();
  ++frames_;
  return frame;
}

}  // namespace hecal::contour
