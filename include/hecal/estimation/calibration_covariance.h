// The covariance of a calibration's (X, Z) from the noise of its stations, for every method
// (the approach of the contour paper, docs/uncertainty.md, applied to the hand–eye estimators).
//
// The estimator is a function of the measurements: (X̂, Ẑ) = g(G_1…G_n, B_1…B_n) with
// G_i = T_base_gripper_i and B_i = T_camera_target_i as the devices report them (eye-to-hand,
// A_i = G_i⁻¹: problem.h). The input noise is G_i = Ĝ_i · Exp(δG_i), B_i = B̂_i · Exp(δB_i)
// (right perturbations, docs/conventions.md, pose_sigma.h) with δG_i ~ N(0, ΣG_i), δB_i ~ N(0,
// ΣB_i) independent: a 12n-dimensional input with block-diagonal covariance (StationNoise). The
// output is (X, Z) ∈ SE(3)², its covariance 12 × 12 over (δX, δZ), right perturbations, (ω, v)
// order each. Three ways:
//  - kLinear: first order. For `ml` the inverse Gauss–Newton information at the optimum (ml.h;
//    free, and the first-order covariance of the ML estimate). For every other method the
//    first-order propagation through the solver itself, J Σ Jᵀ with J by central differences
//    along the Cholesky columns of Σ (uncertainty/first_order.h): 24n solves.
//  - kUnscented: the Unscented Transform through the solver (uncertainty/unscented.h, default
//    symmetric set with w0 = 1 − n_in/3: points at ±√3σ of one measurement component each):
//    24n + 1 solves (fewer when a device has no noise).
//  - kMonteCarlo: `samples` perturbed data sets solved (uncertainty/monte_carlo.h), with the
//    sampling error of each standard deviation; the reference the others are checked against.
//  - kInformation: no solves: the inverse Fisher information I⁻¹ = (Σ_i J_iᵀ Σ_i⁻¹ J_i)⁻¹ of
//    the noise model, evaluated at the measurements and the estimate, Σ_i from station i's
//    robot and camera covariances (StationNoise, station_covariance.h; bound.h's formula; for
//    ml the same as its kLinear, whatever noise model was chosen). It is the first-order covariance
//    of an efficient estimator, so for the closed forms and strobl it is a lower bound
//    (Cramér–Rao): their actual covariance is larger by their inefficiency (docs/accuracy.md: 1–3×
//    in RMSE on the thesis protocol). O(n) time and memory, the only one that stays cheap at
//    10⁴–10⁵ stations.
// The solver at a perturbed data set (Resolve): the closed-form methods exactly as on the data;
// `ml` and `strobl` refined from the calibration's own (X̂, Ẑ) with its noise model held fixed
// (the sigmas used, given or estimated; the perturbations are small, so the start is in the
// right basin and re-running every closed-form start would only cost time).
// Default per method (DefaultCovarianceMethod): kLinear for ml (validated: NEES and coverage in
// docs/uncertainty.md); for the others kUnscented (a numeric linearisation costs the same solves) up to
// kMaxUnscentedStations stations and kInformation above, where the UT would need 24n + 1 solves
// and a 12n × 12n input covariance.
// Limits: the noise model is Gaussian and is the one used by the calibration (given or
// estimated sigmas); near degenerate geometry the estimators are biased and strongly nonlinear,
// and no method here captures that fully (Monte Carlo comes closest).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/covariance_method.h"
#include "hecal/estimation/pose_sigma.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation {

// Right-perturbation covariances of each station's robot pose T_base_gripper_i (as measured,
// whatever the setup) and camera pose T_camera_target_i.
struct StationNoise {
  std::vector<Matrix6d> robot;
  std::vector<Matrix6d> camera;
  // The same sigmas at every station (PoseCovariance).
  static StationNoise Uniform(size_t stations, const PoseSigma& robot, const PoseSigma& camera);
};

// The method of `result` solved on `problem`: closed-form methods directly; ml and strobl
// refined from (result.X, result.Z) with result's sigmas fixed and `options`' robust loss (ml by
// RefineMlFromGoodStart, ml.h: no closed-form starts, pose only; with result.station_scale of a
// heavy-tailed fit, `kept` says which of the result's stations `problem` holds — empty: all).
handeye::Solution Resolve(const handeye::Problem& problem, const CalibrationResult& result,
                          const CalibrateOptions& options, const std::vector<bool>& kept = {});

// The covariance of `result` (computed by Calibrate(problem, calibrate_options)) under `noise`,
// by options.method (nullopt: DefaultCovarianceMethod). Here kLinear is always the numeric
// propagation through the solver, for ml too (Calibrate uses ml's analytic information instead;
// the two agree to first order, which the tests check). kInformation uses `noise` as well (with
// uniform noise it equals FirstOrderBound at result's sigmas). kNone returns nullopt. Throws
// std::invalid_argument when the noise does not have one matrix per station or the information is
// singular, and hecal::DegenerateError when a solve fails at a sigma point (UT, linear).
std::optional<CalibrationCovariance> PropagateCovariance(const handeye::Problem& problem,
                                                         const CalibrationResult& result,
                                                         const CalibrateOptions& calibrate_options,
                                                         const StationNoise& noise,
                                                         const CovarianceOptions& options);

}  // namespace hecal::estimation
