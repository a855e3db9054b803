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
// (docs/uncertainty.md): mean NEES in its 95% band at n = 8 and 15, both setups, with the model
// right. The REML point is kept (NoiseEstimate::reml_variances). Above 100 stations (588
// residual degrees of freedom; the correction is then ≈ 1%) the REML point is used as it is: the
// grids cost 16² + 24² likelihood evaluations of O(n) each per estimate (`hecal calibrate` on
// the 50-station MoveIt set: 0.30 s in all with the model check).
//
// Richer noise models (when the camera noise is estimated and n ≥ kAnisotropicMinStations).
// Two ways real noise departs from the isotropic, equally split model matter for the covariance
// of X, and both are identifiable from poses:
//  - Anisotropic camera noise. A PnP pose has a shape the isotropic model cannot take (tilt 20×
//    its spin, depth 10× its lateral position; station_covariance.h): the isotropic σ_cr then
//    overstates the spin and understates the tilt. Two more camera variances in the camera
//    frame, the tilt excess (rotation about x, y) and the depth excess (translation along z), on
//    top of the isotropic part, are identifiable because those axes turn with the camera pose
//    B_i from station to station while the isotropic parts do not.
//  - Unequal rotation noise of robot and camera (both estimated). A robot rotation error turns
//    the target about the flange, so it moves the target by the lever arm (|t| of X·B_i,
//    eye-in-hand: ~0.5 m) and shows in the translation residual, correlated with the rotation
//    residual; a camera rotation error (the target's orientation) does not. So the robot's and the
//    camera's rotation variances are identifiable apart (eye-in-hand clearly; eye-to-hand only
//    through the target's offset on the flange, weakly). Measured: robot 1°, camera 0.2°,
//    n = 15, REML gives 1.03° / 0.23°.
// What is not identifiable: the robot/camera split of the TRANSLATION noise (both isotropic,
// both enter every translation residual alike), which stays tied (equal split), and the split of
// the anisotropy (given to the camera: a robot's encoders give a nearly isotropic flange pose,
// a PnP pose is anisotropic).
// Choice. After the isotropic fit, EstimateNoise fits each richer model (camera excess: 2 more
// variances; robot rotation apart: 1; both: 3; the last two only when neither side is given),
// started from the isotropic REML point, and compares restricted likelihoods on the stations the
// isotropic fit kept: a model is eligible when 2 (ℓ_R(rich) − ℓ_R(isotropic)) exceeds the χ²
// quantile at 95% for its extra variances (3.84, 5.99, 7.81; with variances on their boundary
// under the isotropic model the null distribution is a χ̄² mixture and the real level is lower,
// about 2% for the excess), and of the eligible ones the largest ℓ_R − (extra variances) wins
// (Akaike). On isotropic, equally split data a richer model is chosen about one time in 20–50.
// Identifiability on the data set at hand: a richer model is eligible only when each group it
// shares with the isotropic model (the rotation and translation variances it splits or adds to)
// rests on more than 2 effective degrees of freedom at its REML point, ν_g = θ_g² /
// (S⁻¹)_gg with S_gh = tr(P Q_g P Q_h) (Var θ̂_g = 2 (S⁻¹)_gg, and a χ²(ν) estimate has
// Var = 2θ²/ν). Below 2 the inverse-gamma posterior of that variance has no mean: the data
// cannot bound it, and the REML point sits on a boundary that the likelihood-ratio test then
// rewards. The extra variances themselves are not held to it: a small robot rotation variance
// beside a large camera one (camodocal-artag, docs/uncertainty.md) has few effective degrees of
// freedom because it is near zero, and that is what the model says. Measured: on the 8-station data
// set whose translation sigma collapsed (docs/uncertainty.md, trial 182 of (b)) the model with the
// camera excess and the robot's rotation apart had ν = 0.00 for the shared translation variance
// (the depth excess takes the same residuals) and 0.11 for the depth excess; it gave σ_t = 0.062 mm
// for a translation-equivalent truth of 0.72 mm and X's NEES 509. Without it the isotropic model is
// chosen: σ_t 0.174 mm, NEES 73 — still low, because the isotropic translation group itself rests
// on ν ≈ 2 there. The minimum of kAnisotropicMinStations: up to five variances from 6n − 12
// residual degrees of freedom; at n = 8 that is 36, 7–9 per variance, the fewest at which the REML
// estimates are bounded away from "anything" (relative σ error √(1/(2ν)) ≈ 0.25) and the
// likelihood-ratio statistic is near its χ² limit. Every estimated group is a posterior mean like
// the isotropic ones: with more than two groups a joint grid is too costly (16⁵ points), so each
// group's posterior mean is taken with the others held at their REML values (a conditional
// posterior mean, narrower than the marginal). Where that matters was measured: on the 8-station
// data set whose translation sigma collapsed with a richer model (docs/uncertainty.md: 0.062 mm
// for a translation-equivalent truth of ≈ 0.7 mm), the joint mean over a 16³ + 24³ grid was 0.071
// mm — the posterior itself sat there (that model is now ineligible, above), so the joint grid, 7×
// the cost, is not used. NoiseEstimate::richer says a
// richer model was chosen; robot() and camera() then report the separate rotation sigmas,
// camera_excess() the excess. Not used when the camera noise is given (--camera-sigma). Cost: up to
// three more REML fits per estimate (`hecal simulate --stations 2000 --trials 2 --method ml
// --estimate-noise`: 4.3 s before, 7.2 s with them, one thread), on at most
// kModelChoiceStations stations (below).
// Infeasible variances: trial steps and grid points whose variances leave a station's Σ_i not
// positive definite (numerically) count as ℓ_R = −∞; a richer model whose REML point is such a
// point is not a candidate, a posterior mean that is one is replaced by the REML point, and
// when the chosen model's own estimate is one EstimateNoise throws DegenerateError naming the
// station noise model (the data do not determine a variance, e.g. poses of a wrong target).
//
// Heavy tails (student_t.h; fitted by ml, ml.h, on top of the model chosen here). The models
// above are Gaussian. Heavy-tailed noise (Student-t(3) per pose component: docs/uncertainty.md,
// (c)) is taken by a multivariate Student-t model of the station residuals, a Gaussian scale
// mixture on these same variance components: given the EM weights w_i, EstimateNoise runs
// unchanged on the components Q_ik / w_i and returns the t model's scale; ν by profile
// likelihood, kept only when the boundary likelihood-ratio test prefers it at 5%.
// NoiseEstimate::student_t_dof and station_scale carry it. The collapse rules above apply as
// they are: the posterior mean of each scale variance, the ν_g > 2 eligibility of the richer
// models (both on the weighted components).
//
// Outlier test (Baarda's data snooping, multivariate form). Station i's statistic is
//   included:  T_i = r̂_iᵀ C_i⁺ r̂_i,  C_i = Σ_i − J_i N⁻¹ J_iᵀ  (its residual covariance)
//   excluded:  T_i = r̂_iᵀ (Σ_i + J_i N⁻¹ J_iᵀ)⁻¹ r̂_i   (prediction from the other stations)
// ~ χ²(d), d = rank C_i, when the variances are known. The station is an outlier when T_i
// exceeds the quantile of the false-alarm probability α per station (default: the two-sided 3σ
// level, α = 0.0027; χ² 20.06 for 6 degrees of freedom). Flagged stations are
// excluded from the noise estimate and the test is repeated until the flags are stable, so a
// gross outlier cannot inflate the estimated sigmas and hide itself (at most (n − 3)/2 stations
// are excluded; beyond that the flags are reported but nothing is excluded). "Stable" is: fewer
// than n · kStableFlagsFraction flags changed — no change at all below 1000 stations; at 10⁵
// inliers the 3σ level flags ~270 and the next round changes ~28, each later round costing a
// full variance iteration for a change in σ of order 10⁻⁵.
// Estimated variances (StationTestOptions::estimated; station_selection.h uses it). When the
// variances were estimated from the included stations, T_i is judged against a scale that is
// itself a random variable with ν = 6m − 12 degrees of freedom (m included stations) — at 8
// stations only 30–36 — and the χ² quantile is too small: a good station left out by the
// consensus (which leaves out the largest residuals) and tested against the scale of the 7
// others made 4.5% of clean 8-station sets lose a station instead of the 2.1% that 0.27% per
// station gives (docs/uncertainty.md, "Outlier test at few stations"; with F and a level of 1%
// per set, station_selection.h: 2.0%). With one common scale factor the exact reference is
// Fisher's F (Koch 1999; Pope's τ test, A. J. Pope, "The statistics of residuals and the detection
// of outliers", NOAA TR NOS 65 NGS 1, 1976): with Ω = Σ_included r̂ᵀ Σ⁻¹ r̂ the weighted residual
// energy at the same variances,
//   excluded:  (T_i / d) / (Ω / ν) ~ F(d, ν)                    (the scale from the others)
//   included:  (T_i / d) / ((Ω − T_i) / (ν − d)) ~ F(d, ν − d)   (the same, leave-one-out:
//              the externally studentised statistic, scale without station i)
// Both ratios are free of the variances' common scale, so they hold for the REML point and the
// posterior mean alike. With several variance groups there is no single scale factor; the F
// reference with the total ν is then an approximation (a group resting on fewer degrees of
// freedom has heavier tails) that is exact when one group dominates the station's residual;
// measured: eye-in-hand, noise estimated on both sides, 2.5% of clean sets at n = 8 and 15
// against the 1% asked (the translation group rests on a few effective degrees of freedom).
// The threshold is never below the χ² one: when part of Σ is known (the PnP covariances of
// `calibrate --images`) and overstates the real noise, Ω is small and the scale-free F would
// shrink the threshold below what the known part alone allows (it rejected 2 of 8 good views of
// a rendered set whose robot poses are exact). StationTest::threshold is the T_i at which the
// test fires.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/loop_residual.h"
#include "hecal/estimation/pose_sigma.h"
#include "hecal/estimation/station_covariance.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation {

inline constexpr double kStableFlagsFraction = 1e-3;
// 1 − erf(3/√2): the two-sided 3σ level, the outlier test's default false-alarm probability.
inline constexpr double kThreeSigmaFalseAlarm = 1.0 - 0.99730020393673979;
// The richer models above: fewest stations.
inline constexpr size_t kAnisotropicMinStations = 8;
// Model choice at scale: above this many stations the isotropic and the richer models are
// fitted and compared (above) on this many stations evenly spread over the recording order
// (station ⌊j n / 2000⌋, j = 0 … 1999: the whole trajectory), and only the chosen model is
// fitted on all stations, started from the subsample's REML point; likelihood_ratio is then
// the subsample's. 2000 stations give the test 11988 residual degrees of freedom (a σ error of
// ≈ 1% per variance), and the choice costs the same at any n above it, so the noise estimate
// is one O(n) fit instead of four. Every fit costs O(n · groups²) with per station only
// fixed-size 6×6 and 6×12 products (noise_estimation.cc, VarianceStep).
inline constexpr size_t kModelChoiceStations = 2000;

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
  // Also try the richer models (above), chosen by the likelihood-ratio test.
  bool richer = false;

  // The rule above: both given → all known; one given → the other side's rotation and
  // translation estimated; none → equal split (rotation group, translation group); estimated
  // groups reported as posterior means (above); the richer models tried when the camera noise
  // is estimated.
  static NoiseSpec FromSigmas(const std::optional<PoseSigma>& robot,
                              const std::optional<PoseSigma>& camera);
  bool AnyEstimated() const;
  int NumGroups() const;
};

struct StationTest {
  double chi2 = 0.0;       // r_iᵀ Σ_i⁻¹ r_i at the linearisation point
  double statistic = 0.0;  // T_i above
  int dof = 0;             // its degrees of freedom
  double threshold = 0.0;  // T_i beyond which the station is an outlier (header)
  bool outlier = false;    // T_i > threshold
};

// The outlier test's level and reference distribution (header, "Outlier test").
struct StationTestOptions {
  double false_alarm = kThreeSigmaFalseAlarm;  // α per station
  bool estimated = false;  // variances estimated from the included stations: F, not χ²

  // core/options_check.h: false naming StationTestOptions.false_alarm (not in (0, 1)).
  bool IsValid(std::string* why) const;
};

struct NoiseEstimate {
  NoiseVariances variances{};       // known or estimated, indexed by NoiseComponent
  NoiseVariances reml_variances{};  // the REML point estimate (= variances without posterior)
  std::vector<StationTest> stations;
  bool converged = true;          // the variance iteration converged (always, if none estimated)
  int iterations = 0;             // variance iterations (0 if none estimated)
  bool richer = false;            // a richer model (above) was chosen
  double likelihood_ratio = 0.0;  // 2 (ℓ_R(rich) − ℓ_R(isotropic)): the chosen or the largest
  // Heavy tails (student_t.h; set by ml): ν of the Student-t model when it was chosen, else 0,
  // and then `variances` are its scale; station_scale[i] multiplies station i's covariance
  // (κ_ν / w_i; empty: 1 everywhere). student_t_ratio: its likelihood-ratio statistic against
  // the Gaussian model (also when not chosen; 0 when not tried).
  double student_t_dof = 0.0;
  std::vector<double> station_scale;
  double student_t_ratio = 0.0;

  PoseSigma robot() const;
  PoseSigma camera() const;
  // The camera's tilt (rotation) and depth (translation) excess σ; zero unless a richer model with
  // it was chosen.
  PoseSigma camera_excess() const;
};

// Estimates the unknown variances of `spec` and tests every station. `length_scale`: see
// LengthScale. Requires at least 3 stations.
NoiseEstimate EstimateNoise(const std::vector<StationLinearization>& stations,
                            const NoiseSpec& spec, double length_scale);

// The outlier test above for every station at fixed variances and a fixed set of included
// stations (the linear re-fit uses those only): the included statistic for included stations,
// the prediction from the others for excluded ones. Throws hecal::InputError when
// !options.IsValid.
std::vector<StationTest> TestStations(const std::vector<StationLinearization>& stations,
                                      const std::vector<bool>& included,
                                      const NoiseVariances& variances,
                                      const StationTestOptions& options = {});

// Starting values for the estimated variances of `spec` (known ones copied) from the raw
// residual energies: a rotation group gets Σ|ω_i|² / Σ tr(ω block of Q_ik); a translation group
// the same on the v parts, net of what the rotation variances already explain there.
NoiseVariances InitialNoiseGuess(const std::vector<StationLinearization>& stations,
                                 const NoiseSpec& spec, double length_scale);

// The largest relative change of one variance between two estimates, |a_k − b_k| /
// max(|a_k|, |b_k|) over the components (0 where they are equal): the convergence test of the
// noise estimation's iterations and of ml's alternation with it.
double MaxRelativeChange(const NoiseVariances& a, const NoiseVariances& b);

// χ² quantile of the two-sided 3σ level for 1–6 degrees of freedom.
double ThreeSigmaChiSquare(int dof);

}  // namespace hecal::estimation
