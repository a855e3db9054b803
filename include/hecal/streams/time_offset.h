// The time offset between two streams, fitted jointly with X and Z (docs/streams.md).
//
// Convention (time_offset_search.h): a camera sample stamped t was taken at robot-clock time
// t + offset.
//
// The joint maximum-likelihood fit over (X, Z, offset) is split as a profile: for an offset δ
// the stations' poses are re-paired (the robot stream smoothed at t + δ, stream_stations.h)
// and ml's cost is minimised over X and Z with the noise model held fixed,
//     χ²(δ) = min over X, Z of Σ_i r_iᵀ Σ_i⁻¹ r_i         (ml.h),
// and δ̂ minimises χ²(δ) — the same optimum as minimising over all three at once. δ̂ is found by
// scanning χ² over the search window on a grid (and at the angular-speed correlation's value,
// time_offset_search.h, which slow motion can leave far off), then by Brent's method (Brent 1973,
// "Algorithms for Minimization without Derivatives", ch. 5) within one grid step of the best.
//
// Uncertainty (first order, the same Gaussian approximation as ml's covariance): the profile's
// curvature gives the offset's variance, σ_δ² = 2 / (d²χ²/dδ²) (three points at δ̂ ± h, h chosen
// so that χ² rises by about 4); and the slope b = d(X̂, Ẑ)/dδ of the profile's optimum (right
// perturbations, the 12 (δX, δZ) components) gives the joint covariance
//     Cov(X, Z) = C(δ̂) + b σ_δ² bᵀ,     Cov((X, Z), δ) = b σ_δ²,
// C(δ̂) being ml's covariance at the fitted offset: for jointly Gaussian estimates the marginal
// covariance is the conditional one plus the regression on δ, whose coefficient is b.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "hecal/geometry/types.h"

namespace hecal::streams {

// The profile at one offset: ml's cost and its optimum.
struct ProfilePoint {
  double cost = 0.0;
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
};
using Profile = std::function<ProfilePoint(double offset)>;

struct OffsetMinimum {
  double offset = 0.0;
  int evaluations = 0;
  bool on_edge = false;  // the minimum lies on the edge of [low, high]
};

// δ̂ in [low, high]: χ² at `start` and on the grid low, low + step, …, high; then Brent within
// ±step of the best, to `tolerance` seconds.
OffsetMinimum MinimiseProfile(const Profile& profile, double start, double low, double high,
                              double step, double tolerance);

struct OffsetUncertainty {
  double sigma = 0.0;                   // seconds
  Eigen::Matrix<double, 12, 1> slope;   // b above: (δX, δZ) per second
  Eigen::Matrix<double, 12, 12> added;  // b σ_δ² bᵀ
  bool curved = true;  // false: χ² does not rise around δ̂ (no motion: δ not observable)
};

// σ_δ and b at the minimum δ̂ (its profile point `at`), from a first step `step` (seconds).
OffsetUncertainty ProfileUncertainty(const Profile& profile, double offset, const ProfilePoint& at,
                                     double step);

}  // namespace hecal::streams
