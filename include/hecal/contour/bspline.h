// Closed uniform cubic B-spline contours (Blake and Isard, "Active Contours", 1998, ch. 3;
// docs/contour.md#shape-space): the curve r(s) = Σ_i B(s − i) Q_i over N control points Q_i,
// periodic in s with period N (one unit of s per span), so the curve is C² and closed.
//
// On span k (s = k + u, u ∈ [0, 1)) the four weights of Q_{k−1}, Q_k, Q_{k+1}, Q_{k+2} are
//   b0 = (1 − u)³/6,  b1 = (3u³ − 6u² + 4)/6,  b2 = (−3u³ + 3u² + 3u + 1)/6,  b3 = u³/6
// (indices modulo N). At the knots r(i) = (Q_{i−1} + 4 Q_i + Q_{i+1})/6, which is how curve
// points become control points (Interpolating: the circulant system, solved exactly).
//
// Conventions: points are columns of a 2×N matrix, image coordinates (x right, y down in images;
// the maths does not care). Normal(s) is the tangent turned by −90°, (t_y, −t_x)/|t|: it points
// out of the contour when the control polygon runs counter-clockwise in an x-right, y-up frame
// (SignedArea() > 0), i.e. clockwise on screen.
#pragma once

#include <Eigen/Core>

namespace hecal::contour {

class ClosedBSpline {
 public:
  // Throws hecal::InputError (source "contour") when there are fewer than 4 control points or a
  // coordinate is not finite.
  explicit ClosedBSpline(Eigen::Matrix2Xd control_points);

  // The closed curve through `curve_points` at s = 0, 1, …, N − 1 (the control points solve the
  // circulant system above). Same checks as the constructor.
  static ClosedBSpline Interpolating(const Eigen::Matrix2Xd& curve_points);

  int size() const { return static_cast<int>(control_points_.cols()); }
  const Eigen::Matrix2Xd& control_points() const { return control_points_; }

  // r(s), r'(s) = dr/ds and the unit normal; s is taken modulo N.
  Eigen::Vector2d Point(double s) const;
  Eigen::Vector2d Tangent(double s) const;
  Eigen::Vector2d Normal(double s) const;
  // The weights of the N control points at s: Point(s) = control_points() · Basis(s)ᵀ. Four are
  // non-zero. Linear in the control points, which is what makes the shape space linear.
  Eigen::RowVectorXd Basis(double s) const;

  // `per_span` points per span, s = k / per_span for k = 0 … N·per_span − 1 (per_span ≥ 1).
  Eigen::Matrix2Xd Sample(int per_span) const;
  // The parameters Sample() uses.
  Eigen::VectorXd SampleParameters(int per_span) const;

  // Area enclosed by the curve (shoelace over a fine sampling), signed: > 0 counter-clockwise in
  // an x-right, y-up frame.
  double SignedArea() const;
  // Centroid of the control points.
  Eigen::Vector2d ControlCentroid() const;

 private:
  Eigen::Matrix2Xd control_points_;
};

}  // namespace hecal::contour
