// Method `ml` (hecal's default): the maximum-likelihood estimate of X and Z jointly from the
// ABSOLUTE station poses (docs/handeye-methods.md#maximum-likelihood).
//
// Why absolute poses: the AX = XB motions A_ij = A_j⁻¹ A_i share measurements, so their noise is
// correlated and no per-motion weighting is correct; the n loops Z = A_i X B_i have independent
// noise (one robot and one camera measurement each).
//
// Cost (Gauss–Helmert maximum likelihood to first order):
//        minimise over X, Z ∈ SE(3):   Σ_i ρ( r_iᵀ Σ_i⁻¹ r_i ),   r_i = Log(Z⁻¹ A_i X B_i)
// with Σ_i the first-order covariance of r_i from the robot and camera noise
// (station_covariance.h; it depends on X through the lever arms, so it is evaluated at the
// current estimate and refreshed until X stops moving — 1e-3 rad / 1e-3·L), ρ the optional
// robust loss (robust_loss.h). Solved by Levenberg–Marquardt on SE(3) × SE(3) with right
// perturbations, the 12 × 12 normal equations accumulated from the analytic Jacobians of
// loop_residual.h, robust losses by reweighting (src/estimation/loop_solver.h; at n = 50 half the
// CPU time of the same minimisation through Ceres, to the same optimum).
//
// Noise levels: from --robot-sigma / --camera-sigma when given; otherwise estimated from the
// residuals by REML variance components (noise_estimation.h: one rotation and one translation
// scale split equally between robot and camera, or from 8 stations a richer model when the
// likelihood ratio asks for it — the camera's tilt / depth excess, the robot's rotation apart
// from the camera's; 6n − 12 degrees of freedom), alternating with the pose estimate until the
// variances change by less than 1e-3 (relative). With both sigmas given, `camera_excess` adds
// the anisotropic camera part (zero: isotropic).
//
// Multi-start: every start (normally all closed-form solutions, initialization.h) is refined
// with the same initial noise model and one common whitening (Σ_i evaluated at the start of
// lowest negative log-likelihood Σ ρ(r_iᵀΣ_i⁻¹r_i) + Σ log det Σ_i; Σ_i depends on X only
// through the lever arms, so this moves no minimum and makes the costs directly comparable);
// the lowest-cost optimum is kept and then refined with Σ_i refreshed at it. Starts are tried
// in order of their initial cost; a start within 2° (and 0.035·L in translation) of an optimum
// already found, for both X and Z, is skipped: it lies in that optimum's basin (wrong minima
// of these problems are ≥ 9° away in the n = 5, σ = 1 study), and skipping keeps the typical
// cost at a few solves.
// Starts on demand: the caller's starts may be few — StartingSolutions (initialization.h) gives
// one, Shah's closed form on every station, and the outlier rejection's later rounds the last
// fit. The optimum reached from them is trusted when a start lies within the basin distance above
// (2°, 0.035·L) of it — a start that far from a wrong minimum would be a closed form tens of
// degrees off — and, with both sigmas given and no robust loss, its cost Σ r_iᵀΣ_i⁻¹r_i is
// within the 99.9% point of χ²(6n − 12), the cost's distribution at the optimum under the noise
// model (a wrong minimum's residuals are not noise). Otherwise every closed-form start of
// initialization.h joins the multi-start above, as all of them did for every solve before (at
// n = 50 the closed forms were 2.4 ms of the 6.3 ms default `ml` path; docs/bench.md). With the
// sigmas estimated the cost says nothing (the noise is fitted to it), so only the distance test
// applies. A false alarm costs time, not accuracy: the multi-start keeps the lowest optimum.
// Good start (RefineMlFromGoodStart): re-solving perturbed or reduced data from a calibration's
// own estimate (the model check's jackknife, covariance propagation, resampling) needs neither
// the closed-form starts nor the noise estimate, station tests and covariance; it runs the same
// refinement from that one start with the noise model given and returns the pose only.
// Heavy tails (student_t.h): with neither sigma given and at least kStudentTMinStations
// stations, after the Gaussian alternation above, the multivariate Student-t model of the station
// residuals is tried: ν by profile likelihood at the Gaussian fit, kept only when the boundary
// likelihood-ratio test prefers it over the Gaussian at 5%. Then EM: the weights
// w_i = (ν + 6)/(ν + r_iᵀ S_i⁻¹ r_i) at the current fit, the variance components re-estimated on
// the components Q_ik / w_i (REML, posterior means, richer models as above), the pose re-solved
// with Σ_i = κ_ν S_i / w_i, until the variances change by less than 1e-3 (relative).
// NoiseEstimate::student_t_dof and station_scale carry the result; its station tests stay the
// Gaussian fit's. Not tried when a sigma is given: the latent scale of a station multiplies its
// whole covariance, a given sigma included. Not tried in the outlier
// rejection's fits (station_selection.h), which test under the Gaussian model.
//
// Planar robots (MlOptions::fixed, handeye/planar.h): the same on the surface where one
// coordinate of X's translation has its given value.
// Covariance: the Gauss–Newton inverse information (Σ_i w_i J_iᵀ Σ_i⁻¹ J_i)⁻¹ at the optimum
// (12 × 12 over (δX, δZ), right perturbations, (ω, v) order; w_i = ρ'(s_i) the robust weights,
// 1 without a robust loss), with the estimated variances when the sigmas were estimated.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/noise_estimation.h"
#include "hecal/estimation/pose_sigma.h"
#include "hecal/estimation/robust_loss.h"
#include "hecal/handeye/planar.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation {

struct MlOptions {
  std::optional<PoseSigma> robot_sigma;   // estimated when absent (see above)
  std::optional<PoseSigma> camera_sigma;  // estimated when absent
  // With both sigmas given: the camera's tilt / depth excess of the anisotropic noise model
  // (noise_estimation.h), e.g. to refit at a result's noise model; zero: isotropic.
  PoseSigma camera_excess;
  RobustLoss robust_loss = RobustLoss::kNone;
  double robust_scale = kOutlierLevelScale;  // whitened units per component (robust_loss.h)
  int max_noise_iterations = 10;             // pose / variance alternations, at least 1
  // With neither sigma given, from kStudentTMinStations stations and no robust loss: also try
  // the heavy-tailed Student-t model (student_t.h, "Heavy tails" above).
  bool heavy_tails = true;
  // Per-station multipliers of Σ_i (a Student-t fit's κ_ν / w_i, NoiseEstimate::station_scale),
  // to refit at a result's noise model; empty: 1 everywhere.
  std::vector<double> station_scale;
  // "Starts on demand" above: when the optimum from `starts` may be a wrong minimum, refine from
  // every closed-form start too. Off: `starts` only (e.g. to study one start's basin).
  bool starts_on_demand = true;
  // Planar robots (handeye/planar.h): one component of X's translation given; the minimisation
  // stays on that constraint and the covariance is the constrained inverse information (zero
  // along the fixed coordinate). The starts should come from handeye::FixedStart: the closed
  // forms of "Starts on demand" do not apply to planar data and are not tried.
  std::optional<handeye::FixedTranslation> fixed;

  // core/options_check.h: false naming MlOptions.robot_sigma / .camera_sigma (negative or not
  // finite; no upper bound: the estimate of one refinement seeds the next), .robust_scale (not
  // positive and finite), .max_noise_iterations (below 1) or .station_scale (an entry not
  // positive and finite).
  bool IsValid(std::string* why) const;
};

struct MlResult {
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
  Eigen::Matrix<double, 12, 12> covariance;  // (δX, δZ)
  NoiseEstimate noise;                       // variances used, per-station tests
  bool sigmas_estimated = false;
  double cost = 0.0;        // Σ ρ(r_iᵀ Σ_i⁻¹ r_i) at the optimum
  int solves = 0;           // minimisations run (all starts and refreshes)
  int starts_refined = 0;   // starts actually refined (others were skipped)
  int distinct_minima = 0;  // distinct optima reached from the starts
};

// Throws hecal::DegenerateError for fewer than 3 stations, hecal::InputError when
// !options.IsValid, std::invalid_argument when `starts` is empty.
MlResult RefineMl(const handeye::Problem& problem, const std::vector<handeye::Solution>& starts,
                  const MlOptions& options);

// The heavy-tail stage of RefineMl ("Heavy tails" above) on its Gaussian result `ml` (a RefineMl
// with options.heavy_tails false on the same problem and sigmas): when the Student-t model is
// chosen, X, Z, the covariance, the cost and the noise estimate become the t fit's. Does nothing
// when a sigma is given, below kStudentTMinStations stations or with a robust loss.
void FitHeavyTails(const handeye::Problem& problem, const MlOptions& options, MlResult* ml);

// RefineMl(problem, {start}, options)'s X and Z (the same refinement), without the noise estimate,
// station tests, covariance and cost. Throws hecal::InputError (source "MlOptions.robot_sigma")
// when options lacks the robot or the camera sigma, DegenerateError for fewer than 3 stations.
handeye::Solution RefineMlFromGoodStart(const handeye::Problem& problem,
                                        const handeye::Solution& start, const MlOptions& options);

}  // namespace hecal::estimation
