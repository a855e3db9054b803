// The L2 polish of a target-free hand–eye solution with the robot's pose error in the model
// (docs/global.md, "The L2 polish and the covariance"). The plain polish (epipolar_polish.h)
// treats every bearing pair as independent; but an error of a hand pose moves every pair of
// every motion that uses that station alike, and on a real arm it dominates (0.03° and 0.25 mm
// over a baseline of a few cm is several times the ray noise of detected corners). Its
// covariance is then several times too small.
//
// Model (per station j, i.e. robot pose): the true hand pose is H_j (Exp(ω_j), τ_j) with the
// nuisance η_j = (ω_j, τ_j) ~ N(0, diag(σ_r² I₃, σ_t² I₃)) (radians, metres; a right
// perturbation of the hand pose H_j of global/epipolar_problem.h, independent between stations),
// and the pair residual r (the angular Sampson error, src/estimation/epipolar_residual.h) has
// independent noise of standard deviation σ (radians of ray). Linearised at X:
//   r ≈ r̂ + J δ + G η,   Cov(r) = V = σ² I + G D Gᵀ,   D = blockdiag(σ_r² I₃, σ_t² I₃ per station),
// J the Jacobian in δ = (ω, τ) of X (right perturbation, as the plain polish) and G the one in
// all stations' η. A motion's two stations give every pair of the motion a shared error, and a
// station shared by two motions correlates them.
//
// Noise estimate (EstimateEpipolarNoise): (σ², σ_r², σ_t²) maximise the restricted likelihood
// (REML; Patterson & Thompson 1971, Harville 1977) of the residuals at X, which removes the
// 6 degrees of freedom of X:
//   ℓ_R = −½ (log det V + log det(Jᵀ V⁻¹ J) + r̂ᵀ V⁻¹ r̂ − bᵀ (Jᵀ V⁻¹ J)⁻¹ b),   b = Jᵀ V⁻¹ r̂,
// evaluated through the Woodbury identity in the 6·stations nuisance dimensions
// (V⁻¹ = σ⁻²(I − σ⁻² G D^½ K⁻¹ D^½ Gᵀ), K = I + σ⁻² D^½ GᵀG D^½, det V = σ²ᴺ det K), and
// maximised by golden-section searches over the log-variances, one at a time, repeated until
// none moves by more than 0.5% in σ (at most 8 rounds). A zero
// robot noise is allowed (σ_r, σ_t then come out negligibly small).
// When the robot's noise is known (`robot`: σ_r, σ_t per axis of the nuisance η_j above), σ_r and
// σ_t are held at it and only σ is estimated, by the same search.
//
// Eye-to-hand (H = T_base_gripper⁻¹): the robot's error is a right perturbation δ of its pose
// G = T_base_gripper (pose_sigma.h), so H̃ = Exp(−δ)·G⁻¹ = H·Exp(−Ad(G) δ): as a nuisance of H the
// same rotation noise (rotated by R_G) and a translation noise R_G v + [t_G]× R_G ω — the
// robot's σ_t plus the lever arm of the gripper's position, correlated with the rotation. The
// model takes it isotropic and uncorrelated: HandPoseSigma below maps a known robot noise to
// it, and an estimated σ_t is that of H (larger than the robot's own by the lever arm).
//
// Polish (PolishWithRobotNoise): generalised least squares with the nuisances marginalised, by
// Gauss–Newton: δ = −(Jᵀ V⁻¹ J)⁻¹ Jᵀ V⁻¹ r̂, X ← X (Exp(ω), τ), until δ is below 1e-12; the
// covariance of X is (Jᵀ V⁻¹ J)⁻¹ at the last X (right perturbation (ω, v), radians and metres).
// With σ_r = σ_t = 0 this is the plain polish with the given σ.
//
// Errors: fewer than 7 pairs throw hecal::DegenerateError.
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "hecal/estimation/epipolar_polish.h"
#include "hecal/estimation/pose_sigma.h"
#include "hecal/global/epipolar_problem.h"

namespace hecal::estimation {

struct EpipolarNoise {
  double ray_sigma = 0.0;                // σ: radians of ray
  double robot_rotation_sigma = 0.0;     // σ_r: radians per axis, per hand pose
  double robot_translation_sigma = 0.0;  // σ_t: metres per axis, per hand pose
};

// REML estimate of the three noise levels from the residuals at X (of σ alone when `robot` is
// given: the result's robot levels are then robot's).
EpipolarNoise EstimateEpipolarNoise(const global::EpipolarProblem& problem, const Pose& X,
                                    const std::optional<PoseSigma>& robot = std::nullopt);

// The GLS polish from `start` for the given noise. The result's ray_sigma is noise.ray_sigma and
// its rms the RMS residual at the polished X.
EpipolarPolish PolishWithRobotNoise(const global::EpipolarProblem& problem, const Pose& start,
                                    const EpipolarNoise& noise);

// The robot's pose noise (pose_sigma.h, right perturbation of T_base_gripper) as the nuisance of
// H above: eye-in-hand the same; eye-to-hand σ_r and sqrt(σ_t² + ⅔ σ_r² d²), d² the mean |t|² of
// the stations' T_base_gripper in metres² (σ_r² (|t|² I − t tᵀ) averaged over the axes).
PoseSigma HandPoseSigma(handeye::Setup setup, const PoseSigma& robot, double mean_squared_distance);

struct RobotNoisePolish {
  EpipolarPolish polish;
  EpipolarNoise noise;
  bool robot_given = false;  // σ_r, σ_t were given, not estimated
  int stations = 0;          // distinct hand poses in the problem
};

// Both, twice: the noise estimated at `start` (best: the plain polish's X), the GLS polish, the
// noise re-estimated at its X, the GLS polish again. DegenerateError when the result is not an
// answer: X not finite, its covariance not finite and positive definite, or |t| of X beyond
// `reach` (metres; the search's translation bound). That happens when the motions do not observe
// the length of X's translation — e.g. every motion a rotation of the hand about its own origin,
// whose epipolar constraints are homogeneous in t: the information matrix is then singular and
// the polish may drift without limit.
// With `robot`, the robot's noise is held at it (EstimateEpipolarNoise).
RobotNoisePolish PolishWithEstimatedRobotNoise(
    const global::EpipolarProblem& problem, const Pose& start,
    double reach = std::numeric_limits<double>::infinity(),
    const std::optional<PoseSigma>& robot = std::nullopt);

// What the noise model predicts for a delete-group jackknife of the GLS polish
// (report/global_calibration_check.h): without group g only the motions m with kept[g][m] are
// polished (noise held), d_g = Log(X̂⁻¹ X_(−g)). In the problem linearised at X, d_g = L_g r with
// L_g = M_g − M, M = (Jᵀ V⁻¹ J)⁻¹ Jᵀ V⁻¹ and M_g the same on the kept pairs (zero on the others),
// and Cov(r) = V. So the jackknife covariance C_jk = (G − 1)/G Σ_g (d_g − d̄)(d_g − d̄)ᵀ has the
// mean  E_jk = (G − 1)/G (Σ_g L_g V L_gᵀ − 1/G (Σ_g L_g) V (Σ_g L_g)ᵀ), which accounts for
// groups that overlap (a motion dropped with either of its stations) or repeat (a motion whose
// two stations are in different groups). And per axis k, C_jk,kk = (G − 1)/G Σ_g y_g² with
// y = A_k r Gaussian, A_k's rows those of L_g − L̄ for axis k: its relative standard deviation is
// √(2 tr(S²))/tr(S), S = A_k V A_kᵀ — the Gaussian sampling error of the check, which
// √(2/(G − 1)) overstates the information of when groups overlap.
struct EpipolarJackknife {
  Matrix6d covariance = Matrix6d::Zero();      // E_jk
  Vector6d relative_error = Vector6d::Zero();  // of each C_jk,kk (a variance)
};

// Precondition: every kept set leaves at least 7 pairs; kept[g] has one entry per motion.
EpipolarJackknife ExpectedEpipolarJackknife(const global::EpipolarProblem& problem, const Pose& X,
                                            const EpipolarNoise& noise,
                                            const std::vector<std::vector<bool>>& kept);

}  // namespace hecal::estimation
