// Noise-level estimation from the residuals (variance components) and the per-station outlier
// test, both on the problem linearised at an estimate (X, Z).
//
// Model. Station i's residual r_i = Log(Z⁻¹ A_i X B_i) (loop_residual.h) has, to first order,
//        r_i ≈ r_i(X, Z) − J_i δ,   Cov(r_i) = Σ_i = Σ_k θ_k Q_ik        (station_covariance.h)
// with δ = (δX, δZ) ∈ R¹² and the four variances θ = (σ_gr², σ_gt², σ_cr², σ_ct²) of the robot
// (g) and camera (c) rotation / translation noise. Some θ_k are known (--robot-sigma /
// --camera-sigma); the others are estimated, possibly tied together in groups that share one
// value. From absolute poses alone robot and camera noise are NOT separately identifiable in
// practice (both enter every residual; only the lever-arm structure of Q_ik tells them apart,
// weakly), so when neither is given hecal ties them: σ_gr = σ_cr (one rotation group) and
// σ_gt = σ_ct (one translation group) — an equal split of the noise between robot and camera,
// estimating one rotation and one translation scale from the 6n − 12 degrees of freedom.
// When one side is given, the other side's two variances are estimated.
//
// Estimator: restricted maximum likelihood (REML) of the variance components by Fisher scoring,
// i.e. iterated Helmert / MINQUE estimation (Koch, "Parameter Estimation and Hypothesis Testing
// in Linear Models", 2nd ed. 1999, §3.6; Förstner 1979). With W = blockdiag(Σ_i⁻¹) at the
// current θ, N = Σ J_iᵀ Σ_i⁻¹ J_i, the re-fitted residuals r̂_i = r_i − J_i N⁻¹ Σ_j J_jᵀ Σ_j⁻¹ r_j,
// P = W − W J N⁻¹ Jᵀ W and Q_g the sum of the components of group g, one step solves
//        Σ_h tr(P Q_g P Q_h) θ_h = r̂ᵀ W Q_g W r̂ − tr(P Q_g P Q_known)       (one row per group)
// for the group variances; each row states that the residual energy of a component equals its
// expectation under the model (unbiased at the current weights). All traces are accumulated
// per station with 12 × 12 matrices, O(n). (Should the G × G system, G ≤ 4 groups, be singular,
// Förstner's ratio update θ_g ← θ_g · r̂ᵀ W Q_g W r̂ / tr(P Q_g) is used.) On a flat likelihood (few
// stations) this iteration can cycle, so every step is safeguarded: it may not decrease the
// restricted log-likelihood
//        ℓ_R(θ) = −½ (Σ_i log det Σ_i + log det N + Σ_i r_iᵀ Σ_i⁻¹ r_i − bᵀ N⁻¹ b)
// and is halved (geometrically) until it does not; a step to a non-positive variance (the
// maximum is on the boundary θ_g = 0) is limited to a factor 10 decrease. Converged when the
// variances change by less than 1e-6 (relative) or no ascent is left. Variances are floored so
// that σ_t ≥ 1e-3 · σ_r · L and σ_r ≥ 1e-3 · σ_t / L (L = LengthScale; real robots and cameras
// are far inside this range) and at 1e-30 absolute, so noise-free data give tiny but positive
// sigmas instead of a division by zero.
//
// Posterior mean (why the estimate cannot collapse). The REML estimate is a point of a
// likelihood that, with few stations, is nearly flat in some directions: in eye-in-hand data the
// translation residuals are dominated by the rotation noise times the lever arms, so the
// translation variance is decided by a few degrees of freedom, and at n = 8 its REML estimate
// ranged over 0.02–3.5 mm for a true 1 mm (thesis protocol, 100 data sets). A covariance built
// on a collapsed estimate is too small by that factor squared (NEES up to 400; mean NEES 23,
// 1σ coverage 47% with the model right). So when the noise is estimated
// (NoiseSpec::FromSigmas) each estimated group's variance — used downstream for the weights and
// the covariance — is the square of its posterior mean σ, E[σ_g | r]², under the restricted
// likelihood exp(ℓ_R(θ)) and a prior flat in each group's σ (p(θ_g) ∝ θ_g^(−1/2)), integrated
// numerically: a log grid of 16 points per group from 10⁻⁶ to 4 times the variance that alone
// would explain the group's whole residual block (beyond it the likelihood falls like
// θ^(−(3n−6)/2)), then a 24-point grid over where that one's weights exceed e⁻²⁵ (a sharp
// likelihood is narrower than a coarse step). Why this prior: it is proper at σ = 0, so a
// likelihood that cannot tell a small variance from zero puts the mean at the scale where the
// data start to constrain it (a flat likelihood on σ ∈ [0, b] gives b/2), not at zero (the scale
// prior 1/θ is improper there and would keep the collapse). Why E[σ]² and not E[θ]: the
// likelihood of a weakly determined variance has a long upper tail, which E[θ] follows (it gave
// 1σ coverage 78% at n = 8 eye-in-hand, σ_t twice the truth on average); for a well-determined
// group with ν degrees of freedom E[σ]² ≈ θ̂ (1 + 2.9/ν) (an inverse-gamma posterior; 1.16 at
// ν = 18), close to the Student-t factor ν/(ν − 2) that makes the expected NEES 6. Measured
// (README "Uncertainty"): mean NEES in its 95% band at n = 8 and 15, both setups, with the model
// right. The REML point is kept (NoiseEstimate::reml_variances). Above 100 stations (588
// residual degrees of freedom; the correction is then ≈ 1%) the REML point is used as it is: the
// grids cost 16² + 24² likelihood evaluations of O(n) each per estimate (`hecal calibrate` on
// the 50-station MoveIt set: 0.30 s in all with the model check).
//
// Anisotropic camera noise (when the camera noise is estimated and n ≥
// kAnisotropicMinStations). A camera pose from PnP has a shape the isotropic model cannot take
// (tilt 20× its spin, depth 10× its lateral position; station_covariance.h): the isotropic
// σ_cr then overstates the spin and understates the tilt. So EstimateNoise also fits the model
// with two more camera variances in the camera frame, the tilt excess (rotation about x, y) and
// the depth excess (translation along z), on top of the isotropic part, and keeps it when the
// restricted likelihood-ratio test rejects the isotropic model: 2 (ℓ_R(rich) − ℓ_R(isotropic))
// > 5.99, the χ²(2) quantile at 95% (with the excesses on their boundary 0 under the isotropic
// model the null distribution is the mixture ¼χ²₀ + ½χ²₁ + ¼χ²₂, so the test's level is about
// 2%; the richer model is chosen on correct data about one time in 50). What is identifiable
// from poses: the camera's own shape is, because the tilt and depth axes turn with the camera
// pose B_i from station to station while the isotropic parts do not; the robot/camera split of
// the isotropic part is not (both enter every residual; for eye-in-hand rotation only their sum
// does), so it stays the equal split of the isotropic model, and all of the anisotropy is given
// to the camera (the prior: a robot's joint encoders give a nearly isotropic flange pose, a PnP
// pose is anisotropic). The minimum of kAnisotropicMinStations: the rich model has four
// variances from 6n − 12 residual degrees of freedom; at n = 8 that is 36, 9 per variance, the
// fewest at which the REML estimates of the excesses are bounded away from "anything" (their
// relative σ error √(2/ν) ≈ 0.5) and the LR statistic is near its χ² limit. Both estimated
// excesses are posterior means like the other groups: with four groups a joint grid is too
// costly (16⁴ points), so each group's posterior mean is taken with the others held at their
// REML values (a conditional posterior mean; for the two isotropic groups of a rich fit this
// ignores their correlation with the excesses, which errs upward as the marginal would).
// The anisotropic model is not used when the camera noise is given (--camera-sigma).
//
// Outlier test (Baarda's data snooping, multivariate form). Station i's statistic is
//   included:  T_i = r̂_iᵀ C_i⁺ r̂_i,  C_i = Σ_i − J_i N⁻¹ J_iᵀ  (its residual covariance)
//   excluded:  T_i = r̂_iᵀ (Σ_i + J_i N⁻¹ J_iᵀ)⁻¹ r̂_i   (prediction from the other stations)
// ~ χ²(rank C_i) under the model. The station is an outlier when T_i exceeds the χ² quantile of
// the two-sided 3σ level (p = 0.0027; 20.06 for 6 degrees of freedom). Flagged stations are
// excluded from the noise estimate and the test is repeated until the flags are stable, so a
// gross outlier cannot inflate the estimated sigmas and hide itself (at most (n − 3)/2 stations
// are excluded; beyond that the flags are reported but nothing is excluded). "Stable" is: fewer
// than n · kStableFlagsFraction flags changed — no change at all below 1000 stations; at 10⁵
// inliers the 3σ level flags ~270 and the next round changes ~28, each later round costing a
// full variance iteration for a change in σ of order 10⁻⁵.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "hecal/estimation/loop_residual.h"
#include "hecal/estimation/pose_sigma.h"
#include "hecal/estimation/station_covariance.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation {

inline constexpr double kStableFlagsFraction = 1e-3;
// The anisotropic model above: fewest stations, and the likelihood-ratio threshold.
inline constexpr size_t kAnisotropicMinStations = 8;
inline constexpr double kAnisotropicLikelihoodRatio = 5.991;

// One station linearised at (X, Z).
struct StationLinearization {
  Vector6d residual;           // r_i
  Matrix6x12d jacobian;        // ∂r_i/∂(δX, δZ)
  NoiseComponents components;  // Q_ik at X
};

std::vector<StationLinearization> LinearizeStations(const handeye::Problem& problem, const Pose& X,
                                                    const Pose& Z);

// Which variances are known and which are estimated.
struct NoiseSpec {
  // Known variances; for estimated ones the starting value (≤ 0: derived from the residuals).
  NoiseVariances variances{};
  // −1: known; g ≥ 0: estimated, one shared value per group g (groups 0–3 at most).
  std::array<int, kNumNoiseComponents> group{-1, -1, -1, -1, -1, -1};
  // Report the posterior mean σ² of the estimated groups (above) instead of the REML point.
  bool posterior_mean = false;
  // Also try the anisotropic camera model (above; the camera excesses are then estimated as
  // groups of their own when the likelihood-ratio test chooses it).
  bool anisotropic = false;

  // The rule above: both given → all known; one given → the other side's rotation and
  // translation estimated; none → equal split (rotation group, translation group); estimated
  // groups reported as posterior means (above); the anisotropic model tried when the camera
  // noise is estimated.
  static NoiseSpec FromSigmas(const std::optional<PoseSigma>& robot,
                              const std::optional<PoseSigma>& camera);
  bool AnyEstimated() const;
  int NumGroups() const;
};

struct StationTest {
  double chi2 = 0.0;       // r_iᵀ Σ_i⁻¹ r_i at the linearisation point
  double statistic = 0.0;  // T_i above
  int dof = 0;             // its degrees of freedom
  bool outlier = false;    // T_i > χ²_dof(0.9973)
};

struct NoiseEstimate {
  NoiseVariances variances{};       // known or estimated, indexed by NoiseComponent
  NoiseVariances reml_variances{};  // the REML point estimate (= variances without posterior)
  std::vector<StationTest> stations;
  bool converged = true;          // the variance iteration converged (always, if none estimated)
  int iterations = 0;             // variance iterations (0 if none estimated)
  bool anisotropic = false;       // the anisotropic camera model was chosen
  double likelihood_ratio = 0.0;  // 2 (ℓ_R(rich) − ℓ_R(isotropic)), when it was fitted

  PoseSigma robot() const;
  PoseSigma camera() const;
  // The camera's tilt (rotation) and depth (translation) excess σ; zero unless anisotropic.
  PoseSigma camera_excess() const;
};

// Estimates the unknown variances of `spec` and tests every station. `length_scale`: see
// LengthScale. Requires at least 3 stations.
NoiseEstimate EstimateNoise(const std::vector<StationLinearization>& stations,
                            const NoiseSpec& spec, double length_scale);

// The outlier test above for every station at fixed variances and a fixed set of included
// stations (the linear re-fit uses those only): the included statistic for included stations,
// the prediction from the others for excluded ones.
std::vector<StationTest> TestStations(const std::vector<StationLinearization>& stations,
                                      const std::vector<bool>& included,
                                      const NoiseVariances& variances);

// Starting values for the estimated variances of `spec` (known ones copied) from the raw
// residual energies: a rotation group gets Σ|ω_i|² / Σ tr(ω block of Q_ik); a translation group
// the same on the v parts, net of what the rotation variances already explain there.
NoiseVariances InitialNoiseGuess(const std::vector<StationLinearization>& stations,
                                 const NoiseSpec& spec, double length_scale);

// χ² quantile of the two-sided 3σ level for 1–6 degrees of freedom.
double ThreeSigmaChiSquare(int dof);

}  // namespace hecal::estimation
