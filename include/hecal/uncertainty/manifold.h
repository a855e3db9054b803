// The spaces the uncertainty transforms (unscented.h, monte_carlo.h, first_order.h) work on:
// a type T with a tangent space of dimension Dim(x), a retraction Plus and its inverse Minus.
//
//   Eigen::VectorXd     R^n:     Plus(x, δ) = x + δ,        Minus(y, x) = y − x
//   Eigen::Matrix3d     SO(3):   Plus(R, δ) = R · Exp(δ),   Minus(S, R) = Log(R⁻¹ S)
//   Pose                SE(3):   Plus(T, δ) = T · Exp(δ),   Minus(U, T) = Log(T⁻¹ U),  δ = (ω, v)
//   std::vector<Pose>   SE(3)^k: each pose in turn, δ = (δ_0, …, δ_{k−1}) (e.g. (X, Z): 12-D)
//
// These are the right-perturbation retractions of docs/conventions.md, so a covariance on T means
// T = T̂ · Exp(δ), δ ~ N(0, Σ), rotation first — the meaning of every 6×6 covariance in hecal.
//
// WeightedMean finds the mean on the manifold iteratively (the weighted Karcher/Fréchet mean
// of Pennec, "Intrinsic statistics on Riemannian manifolds", JMIV 2006, Alg. 1, with the
// retraction above): x ← x ⊞ Σ w_i (y_i ⊟ x) until the step is below tolerance or stops
// shrinking (it is then rounding noise, amplified by large weights such as the scaled UT's
// with small α). On R^n (kFlat) it is the weighted average: one step. The weights must sum to
// 1; negative ones are allowed (the unscented centre weight can be negative).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "hecal/core/options_check.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "hecal/geometry/types.h"

namespace hecal::uncertainty {

template <class T>
struct Manifold;  // specialised below; add one to use a new type with the transforms

template <>
struct Manifold<Eigen::VectorXd> {
  static constexpr bool kFlat = true;  // the weighted mean is one step
  static int Dim(const Eigen::VectorXd& x) { return static_cast<int>(x.size()); }
  static Eigen::VectorXd Plus(const Eigen::VectorXd& x, const Eigen::VectorXd& delta) {
    return x + delta;
  }
  static Eigen::VectorXd Minus(const Eigen::VectorXd& y, const Eigen::VectorXd& x) { return y - x; }
};

template <>
struct Manifold<Eigen::Matrix3d> {
  static constexpr bool kFlat = false;
  static int Dim(const Eigen::Matrix3d&) { return 3; }
  static Eigen::Matrix3d Plus(const Eigen::Matrix3d& R, const Eigen::VectorXd& delta) {
    return R * so3::Exp(delta.head<3>());
  }
  static Eigen::VectorXd Minus(const Eigen::Matrix3d& S, const Eigen::Matrix3d& R) {
    return so3::Log(R.transpose() * S);
  }
};

template <>
struct Manifold<Pose> {
  static constexpr bool kFlat = false;
  static int Dim(const Pose&) { return 6; }
  static Pose Plus(const Pose& T, const Eigen::VectorXd& delta) {
    return T * se3::Exp(delta.head<6>());
  }
  static Eigen::VectorXd Minus(const Pose& U, const Pose& T) { return se3::Log(T.inverse() * U); }
};

template <>
struct Manifold<std::vector<Pose>> {
  static constexpr bool kFlat = false;
  static int Dim(const std::vector<Pose>& x) { return 6 * static_cast<int>(x.size()); }
  static std::vector<Pose> Plus(const std::vector<Pose>& x, const Eigen::VectorXd& delta) {
    std::vector<Pose> y(x.size());
    for (size_t k = 0; k < x.size(); ++k) {
      y[k] = x[k] * se3::Exp(delta.segment<6>(6 * static_cast<Eigen::Index>(k)));
    }
    return y;
  }
  static Eigen::VectorXd Minus(const std::vector<Pose>& y, const std::vector<Pose>& x) {
    Eigen::VectorXd delta(6 * static_cast<Eigen::Index>(x.size()));
    for (size_t k = 0; k < x.size(); ++k) {
      delta.segment<6>(6 * static_cast<Eigen::Index>(k)) = se3::Log(x[k].inverse() * y[k]);
    }
    return delta;
  }
};

struct MeanOptions {
  int max_iterations = 50;   // at least 1
  double tolerance = 1e-13;  // on |Σ w_i (y_i ⊟ x)|, tangent units; finite, 0 or more

  // core/options_check.h: false naming MeanOptions.max_iterations (below 1) or .tolerance
  // (negative or not finite).
  bool IsValid(std::string* why) const {
    if (max_iterations < 1) {
      return Invalid(why, "MeanOptions.max_iterations",
                     "must be at least 1, got " + std::to_string(max_iterations),
                     "give the most iterations of the mean (default 50)");
    }
    if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) {
      return Invalid(why, "MeanOptions.tolerance", "must be a finite number, 0 or more",
                     "give the step size at which the mean stops (default 1e-13)");
    }
    return true;
  }
};

// Weighted mean of `points` on the manifold, started from `initial` (e.g. the unscented centre
// point or the first sample). Returns the last iterate when max_iterations is reached. Throws
// hecal::InputError when !options.IsValid.
template <class T>
T WeightedMean(std::span<const T> points, std::span<const double> weights, const T& initial,
               const MeanOptions& options = {}) {
  RequireValid(options);
  using M = Manifold<T>;
  T mean = initial;
  const int n = M::Dim(mean);
  if (n <= 0) return mean;
  double previous = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
    for (size_t i = 0; i < points.size(); ++i) step += weights[i] * M::Minus(points[i], mean);
    const double size = step.norm();
    if (iteration > 0 && size > 0.5 * previous) break;  // no longer converging: noise
    mean = M::Plus(mean, step);
    if (M::kFlat || size <= options.tolerance) break;
    previous = size;
  }
  return mean;
}

// Σ w_i (y_i ⊟ mean)(y_i ⊟ mean)ᵀ: the weighted covariance in the tangent space at `mean`.
template <class T>
Eigen::MatrixXd WeightedCovariance(std::span<const T> points, std::span<const double> weights,
                                   const T& mean) {
  using M = Manifold<T>;
  const int n = M::Dim(mean);
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(n, n);
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::VectorXd d = M::Minus(points[i], mean);
    covariance.noalias() += weights[i] * d * d.transpose();
  }
  return 0.5 * (covariance + covariance.transpose());
}

}  // namespace hecal::uncertainty
