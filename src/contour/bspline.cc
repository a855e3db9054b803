// Closed uniform cubic B-splines: see bspline.h.
#include "hecal/contour/bspline.h"

#include <Eigen/LU>
#include <cmath>

#include "hecal/core/error.h"

namespace hecal::contour {
namespace {

void Validate(const Eigen::Matrix2Xd& points, const char* what) {
  if (points.cols() < 4) {
    throw InputError("contour", 0,
                     std::string(what) + ": a closed cubic B-spline needs at least 4 points, got " +
                         std::to_string(points.cols()),
                     "give 4 or more points around the contour");
  }
  if (!points.allFinite()) {
    throw InputError("contour", 0, std::string(what) + ": a coordinate is not finite",
                     "give finite x, y for every point");
  }
}

// Span index k ∈ [0, N) and local parameter u ∈ [0, 1) of s (s taken modulo N).
void Locate(double s, int n, int* k, double* u) {
  double wrapped = std::fmod(s, static_cast<double>(n));
  if (wrapped < 0.0) wrapped += n;
  double span = std::floor(wrapped);
  if (span >= n) span = 0.0;  // s just below a multiple of N rounding up
  *k = static_cast<int>(span);
  *u = wrapped - span;
}

int Wrap(int i, int n) {
  return ((i % n) + n) % n;
}

}  // namespace

ClosedBSpline::ClosedBSpline(Eigen::Matrix2Xd control_points)
    : control_points_(std::move(control_points)) {
  Validate(control_points_, "control points");
}

ClosedBSpline ClosedBSpline::Interpolating(const Eigen::Matrix2Xd& curve_points) {
  Validate(curve_points, "curve points");
  const int n = static_cast<int>(curve_points.cols());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);  // circulant (1, 4, 1)/6, always invertible
  for (int i = 0; i < n; ++i) {
    A(i, Wrap(i - 1, n)) += 1.0 / 6.0;
    A(i, i) += 4.0 / 6.0;
    A(i, Wrap(i + 1, n)) += 1.0 / 6.0;
  }
  const Eigen::MatrixXd Q = A.partialPivLu().solve(curve_points.transpose());
  return ClosedBSpline(Q.transpose());
}

Eigen::RowVectorXd ClosedBSpline::Basis(double s) const {
  const int n = size();
  int k = 0;
  double u = 0.0;
  Locate(s, n, &k, &u);
  const double u2 = u * u, u3 = u2 * u;
  Eigen::RowVectorXd b = Eigen::RowVectorXd::Zero(n);
  b(Wrap(k - 1, n)) += (1.0 - u) * (1.0 - u) * (1.0 - u) / 6.0;
  b(k) += (3.0 * u3 - 6.0 * u2 + 4.0) / 6.0;
  b(Wrap(k + 1, n)) += (-3.0 * u3 + 3.0 * u2 + 3.0 * u + 1.0) / 6.0;
  b(Wrap(k + 2, n)) += u3 / 6.0;
  return b;
}

Eigen::Vector2d ClosedBSpline::Point(double s) const {
  return control_points_ * Basis(s).transpose();
}

Eigen::Vector2d ClosedBSpline::Tangent(double s) const {
  const int n = size();
  int k = 0;
  double u = 0.0;
  Locate(s, n, &k, &u);
  const double u2 = u * u;
  // Derivatives of the four weights of bspline.h with respect to u (= s).
  return control_points_.col(Wrap(k - 1, n)) * (-(1.0 - u) * (1.0 - u) / 2.0) +
         control_points_.col(k) * ((9.0 * u2 - 12.0 * u) / 6.0) +
         control_points_.col(Wrap(k + 1, n)) * ((-9.0 * u2 + 6.0 * u + 3.0) / 6.0) +
         control_points_.col(Wrap(k + 2, n)) * (u2 / 2.0);
}

Eigen::Vector2d ClosedBSpline::Normal(double s) const {
  const Eigen::Vector2d t = Tangent(s);
  const double length = t.norm();
  if (!(length > 0.0)) return Eigen::Vector2d::Zero();  // a cusp: coincident control points
  return Eigen::Vector2d(t.y(), -t.x()) / length;
}

Eigen::VectorXd ClosedBSpline::SampleParameters(int per_span) const {
  if (per_span < 1) throw std::invalid_argument("ClosedBSpline::Sample: per_span must be ≥ 1");
  const int count = size() * per_span;
  Eigen::VectorXd s(count);
  for (int i = 0; i < count; ++i) s(i) = static_cast<double>(i) / per_span;
  return s;
}

Eigen::Matrix2Xd ClosedBSpline::Sample(int per_span) const {
  const Eigen::VectorXd s = SampleParameters(per_span);
  Eigen::Matrix2Xd points(2, s.size());
  for (Eigen::Index i = 0; i < s.size(); ++i) points.col(i) = Point(s(i));
  return points;
}

double ClosedBSpline::SignedArea() const {
  const Eigen::Matrix2Xd p = Sample(64);
  double twice = 0.0;
  for (Eigen::Index i = 0; i < p.cols(); ++i) {
    const Eigen::Index j = (i + 1) % p.cols();
    twice += p(0, i) * p(1, j) - p(0, j) * p(1, i);
  }
  return 0.5 * twice;
}

Eigen::Vector2d ClosedBSpline::ControlCentroid() const {
  return control_points_.rowwise().mean();
}

}  // namespace hecal::contour
