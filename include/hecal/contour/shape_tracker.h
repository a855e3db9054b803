// The shape-space Kalman filter that tracks a planar contour through an image sequence (Blake and
// Isard, "Active Contours", 1998: shape space ch. 4, measurement ch. 5–6, the recursive
// estimator ch. 8–10; the contour paper §II: "a Kalman filter follows the contour through the
// images of the sequence, updating the shape vector and estimating its covariance";
// docs/contour.md#shape-space).
//
// Shape space. The template is the initial contour: control points Q0 in image coordinates
// relative to an origin (the principal point), a ShapeSpace (shape_space.h) of dimension k
// over them; the contour of reduced coordinates x has control points Q0 + W x, and the full
// shape vector is S = B x (B = basis(), 6 × k).
//
// State and dynamics (B&I ch. 9, a constant-velocity model, their second-order AR process in its
// simplest form): X = (x, v), v the change of x per frame,
//   x' = x + v,  v' = v  (+ a random acceleration per frame),
//   Q = [C/3  C/2; C/2  C] (white acceleration integrated over one frame),
//   C = (2N / k) q² (WᵀW)⁻¹,
// the acceleration covariance in shape space whose image displacement of the control points
// has mean square q² per coordinate (E‖W a‖² / 2N = q²): q = process_noise, px per frame².
// The first frame starts from x = 0 with C(initial_sigma) and velocity C(initial_velocity_sigma)
// (the same form with those RMS displacements).
//
// Measurement (B&I ch. 6 "Fitting spline templates", §6.4 and ch. 10: the recursive fitting
// algorithm in information form). The curve of the current estimate x_i is sampled at
// points_per_span points per span, s_j; along the unit normal n_j at r_j = r(s_j) an edge is
// searched (edge_search.h) and, when found at offset ν_j, gives one scalar measurement of the
// normal position of the curve,
//   y_j = h_j x + e_j,   y_j = h_j x_i + ν_j,   h_j = n_jᵀ [b_j Wx; b_j Wy]   (1 × k)
// (b_j the B-spline weights of the control points at s_j, Wx, Wy the x and y rows of W; only the
// normal component is measured: the aperture problem). With independent errors e_j ~ N(0, σ²),
//   P⁺ = (P⁻⁻¹ + Σ Hjᵀ Hj / σ²)⁻¹,   X⁺ = P⁺ (P⁻⁻¹ X⁻ + Σ Hjᵀ y_j / σ²),   Hj = [h_j 0 …],
// always relative to the prior (X⁻, P⁻); it is evaluated in the equivalent k × k form of the
// source (push-through identity), which needs no inverse of P⁻. This is repeated `iterations`
// times per frame, each time re-searching along the normals of the current estimate (the
// Gauss–Newton iteration of the iterated extended Kalman filter: n_j and r_j depend on x).
// Outlier gate: an edge is used only when its innovation |ν_j| ≤ gate · sqrt(h_j P_i h_jᵀ + σ²)
// (P_i the covariance of the current estimate, the prior on the first pass).
//
// Measurement σ. Given (measurement_sigma), or estimated every pass from the normal residuals of
// the used edges, σ̂² = Σ (y_j − h_j x_{i+1})² / (m − k), floored at sigma_floor; the final pass
// is solved again with the final σ̂ so that the reported covariance uses it. The residuals
// contain what the model does not explain — edge-location noise, pixel locking, and weak
// perspective's departure from an affinity (perspective_view.h) — so σ̂ grows with the tilt
// instead of the covariance claiming a precision the model cannot reach. Neighbouring
// measurements are taken to be independent: keep points_per_span such that they are several
// pixels apart (the default 8 per span is ~10 px on the paper's target).
//
// Template refinement (refine_template, default on). The first image is the template view: its
// edges are fitted from the given initial contour (a wide prior, initial_sigma), and the fitted
// curve becomes the template Q0 (the shape space is rebuilt on it), so every later S is relative
// to the contour as the edge detector sees it in the first image — a bias common to all frames
// (a sloppy initial contour, the detector's small inward shift on curved edges) cancels. The fit
// has an error e0 (covariance: the first frame's posterior), which no later image observes: the
// tracked x is the contour relative to the fitted template, x = S − e0. So the filter carries e0
// as a constant state e (state (x, v, e), 3k; errors of x and e start as (e0, −e0)), and reports
// the motion since the first view as S = B (x + e) with the covariance of x + e — zero at the
// first frame, and from then on the sum of this image's and the template's uncertainty. (Without
// e the covariance would claim the template is exact: measured on the rendered sequence, the
// rotation terms M21, M12 then sat at a persistent ±2.5σ.) Without refinement the state is
// (x, v), the given contour is the exact template, and S(frame 0) is the offset of the first
// image's edges from it.
//
// Polarity. When search.polarity = 0 and learn_polarity, the sign of the gradient is learnt from
// the first frame (when at least 90% of its used edges agree) and required afterwards.
//
// Lost frames: with fewer than min_edges usable edges (default max(3k, 12)) the frame keeps the
// prediction (updated = false).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "hecal/contour/bspline.h"
#include "hecal/contour/edge_search.h"
#include "hecal/contour/gray_image.h"
#include "hecal/contour/shape_space.h"
#include "hecal/geometry/types.h"

namespace hecal::contour {

struct ShapeTrackerOptions {
  ShapeSubspace subspace = ShapeSubspace::kFull;
  int points_per_span = 8;
  EdgeSearchOptions search;  // range ±10 px, σ_d = 1 px, min gradient 10 grey/px
  int iterations = 4;
  double gate = 3.0;
  std::optional<double> measurement_sigma;  // px; nullopt: estimate (above)
  double sigma_floor = 0.02;                // px
  double initial_measurement_sigma = 1.0;   // px: σ before the first estimate
  double process_noise = 1.0;               // q, px / frame²
  double initial_sigma = 2.0;               // px: RMS error of the initial contour
  double initial_velocity_sigma = 5.0;      // px / frame
  bool refine_template = true;
  bool learn_polarity = true;
  int min_edges = 0;  // 0: max(3k, 12)

  // core/options_check.h: false naming ShapeTrackerOptions.subspace (not a ShapeSubspace),
  // .points_per_span (not 1 … 1000), .iterations (not 1 … 100), .gate, .measurement_sigma,
  // .sigma_floor, .initial_measurement_sigma, .process_noise, .initial_sigma or
  // .initial_velocity_sigma (not above 0 and finite), .min_edges (negative), or the field of
  // search.IsValid (edge_search.h).
  bool IsValid(std::string* why) const;
};

struct TrackedFrame {
  int frame = 0;
  bool updated = false;                          // false: too few edges, the prediction is kept
  Eigen::VectorXd x;                             // reduced coordinates (k)
  Eigen::MatrixXd x_covariance;                  // k × k
  Vector6d shape = Vector6d::Zero();             // S = B x (tx, ty in px)
  Matrix6d shape_covariance = Matrix6d::Zero();  // B P Bᵀ
  Eigen::VectorXd velocity;                      // v (k), per frame
  int edges_searched = 0;                        // normals searched on the last pass
  int edges_found = 0;                           // … with an edge
  int edges_used = 0;                            // … that passed the gate
  double residual_rms = 0.0;  // px: RMS normal residual of the used edges after the update
  double sigma = 0.0;         // px: the measurement σ of the update
  bool sigma_estimated = false;
};

class ShapeTracker {
 public:
  // `control_points`: the initial contour's control points in pixel coordinates; `origin`: the
  // principal point (image coordinates are measured from it). Throws hecal::InputError when
  // !options.IsValid or for bad points and hecal::DegenerateError for a collinear contour
  // (shape_space.h).
  ShapeTracker(const Eigen::Matrix2Xd& control_points, const Eigen::Vector2d& origin,
               const ShapeTrackerOptions& options = {});

  // Predicts (from the second frame on) and updates with one image.
  TrackedFrame Track(const GrayImage& image);

  // The shape space (template relative to the origin; rebuilt after the first frame when the
  // template is refined).
  const ShapeSpace& space() const { return space_; }
  const Eigen::Vector2d& origin() const { return origin_; }
  // The full S of the refined template relative to the given initial contour (zero before the
  // first frame or without refinement).
  const Vector6d& template_shape() const { return template_shape_; }
  int frames() const { return frames_; }
  int polarity() const { return search_.polarity; }
  // The contour of reduced coordinates x, in pixel coordinates.
  ClosedBSpline Curve(const Eigen::VectorXd& x) const;

 private:
  struct Pass;
  Pass Measure(const GrayImage& image, const Eigen::VectorXd& state, const Eigen::MatrixXd& cov,
               double sigma) const;

  ShapeTrackerOptions options_;
  EdgeSearchOptions search_;
  Eigen::Vector2d origin_;
  ShapeSpace space_;
  Vector6d template_shape_ = Vector6d::Zero();
  Eigen::VectorXd state_;                  // (x, v), 2k
  Eigen::MatrixXd covariance_;             // 2k × 2k
  Eigen::MatrixXd unit_shape_covariance_;  // (2N/k)(WᵀW)⁻¹: C for an RMS displacement of 1 px
  double sigma_ = 1.0;
  int frames_ = 0;
};

}  // namespace hecal::contour
