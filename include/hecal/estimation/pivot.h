// Tool-centre-point calibration by pivoting (docs/pivot.md): a tool tip held at one fixed point
// while the robot takes several orientations. From the robot poses T_base_flange_i = (R_i, t_i)
// it estimates the tip offset t_tip (flange frame) and the pivot point p (base frame):
//        R_i t_tip + t_i = p                                                         (P1)
//
// 1. Algebraic start (the classic pivot calibration; Yaniv, "Which pivot calibration?", Proc.
//    SPIE 9415, 2015, §2.1): (P1) stacked as the linear system
//        [R_i  −I] [t_tip; p] = −t_i,   i = 1 … n                                     (P2)
//    solved by linear least squares (column-pivoted QR of the 3n × 6 matrix).
// 2. Geometric maximum-likelihood refinement. The robot reports T̃_i = T_i · Exp(δ_i) (right
//    perturbation, pose_sigma.h), δ_i = (ω_i, v_i) ~ N(0, diag(σ_r² I, σ_t² I)). To first order
//    the residual e_i = R̃_i t_tip + t̃_i − p = R_i (ω_i × t_tip + v_i) has the covariance
//        C_i = σ_t² I + σ_r² R_i [t_tip]× [t_tip]×ᵀ R_iᵀ                               (P3)
//    (rotation noise moves the tip by the lever arm, across the tool; translation noise in every
//    direction). The estimate minimises Σ_i e_iᵀ C_i⁻¹ e_i, the first-order geometric distance of
//    the errors-in-variables model (the Gauss–Helmert model: the true poses profiled out). Since
//    e_i is linear in x = (t_tip, p) with J_i = [R_i  −I], it is found by iterated generalised
//    least squares: C_i at the current t_tip, then the weighted normal equations
//        (Σ J_iᵀ C_i⁻¹ J_i) x = −Σ J_iᵀ C_i⁻¹ t_i                                        (P4)
//    until x changes by less than 1e-12 m (at most kPivotIterations). The fixed point leaves out
//    the derivative of C_i in t_tip, an O(σ_r² |t_tip|) term (for 0.1°, 0.2 m and ±30° tilt about
//    0.01 mm, far below the standard deviation).
// 3. Noise. Given σ_r, σ_t (PivotOptions::sigma) are used as they are. Not given, the shape
//    kPivotNoiseShape (1 mm : 1°, the thesis' "n mm / n deg", docs/thesis-study.md) is scaled by
//    one common factor k from the fit, k² = χ² / (3m − 6) over the m stations used,
//    χ² = Σ e_iᵀ C_i⁻¹ e_i at the shape: σ_t = k mm, σ_r = k°. (σ_r and σ_t are not fitted
//    separately: the split shows only in the residual along the tool, R_i t_tip, which holds
//    translation noise alone, and is weakly determined by a handful of stations.)
// 4. Covariance of x (6 × 6; t_tip then p, m²): the inverse information
//        Σ_x = (Σ J_iᵀ C_i⁻¹ J_i)⁻¹                                                      (P5)
//    at the estimate, with C_i from the sigma used (given, or the estimated k: then the NEES of
//    x follows 6 F(6, 3m − 6), mean 6 (3m − 6) / (3m − 8)).
// 5. Stations: the residual e_i (metres), its standardised size d_i = sqrt(e_iᵀ C_i⁻¹ e_i) with
//    the sigma used, and an outlier flag when d_i² > χ²₃(0.999) = 16.27 with the flag scale
//    k² = median(χ²_i at the shape) / χ²₃(0.5) over the stations fitted, which a gross outlier
//    cannot inflate (with the sigma given, k² is at least 1: a fit pulled by a gross outlier
//    leaves every residual large, and would otherwise flag them all). With reject_outliers the
//    flagged stations
//    are left out and the fit repeated (flags from each new fit, at most kPivotRejectionRounds)
//    until the set stays the same; the rejection stops instead (every station kept, a warning)
//    when it would leave fewer than max(4, ⌈n/2⌉) stations.
// 6. Degeneracy (before the fit, from the rotations alone). With p eliminated, t_tip is
//    observed through the rotation spread S = (1/n) Σ (R_i − R̄)ᵀ (R_i − R̄), R̄ = (1/n) Σ R_i:
//    for a unit v (flange frame), vᵀ S v is the mean squared distance of R_i v from its mean,
//    ≈ the mean squared tilt about the axes perpendicular to v. Its eigenvalues λ₁ ≥ λ₂ ≥ λ₃:
//     - sqrt(λ₁) < kPivotMinTilt: the tool barely rotated; neither t_tip nor p is observable;
//     - sqrt(λ₃) < kPivotMinTilt: the tool rotated about one axis only; the tip's component along
//       that axis (v₃, flange frame) and the pivot's along it (R̄ v₃ normalised, base frame)
//       are not observable (P1 holds for any shift along the common axis; cf. the parallel-axis
//       degeneracy of hand–eye calibration, handeye/observability.h);
//     - after the fit, the same with the noise (as handeye::CheckObservabilityUnderNoise):
//       rotation noise alone spreads R_i v by E|ω × v|² = 2σ_r², so ρ = λ₃ / (2σ_r²) below
//       handeye::kNoiseDegenerate means the axis is observed by noise only.
//    hecal::DegenerateError names the unobservable component and the fix; fewer than 3
//    stations (no degree of freedom for the noise) are refused the same way.
#pragma once

#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/pose_sigma.h"
#include "hecal/geometry/types.h"

namespace hecal::estimation {

// The noise shape scaled when the noise is estimated: 1 mm and 1° per axis.
inline constexpr PoseSigma kPivotNoiseShape{std::numbers::pi / 180.0, 1e-3};
// RMS tilt (radians) below which a direction counts as not rotated: 2°.
inline constexpr double kPivotMinTilt = 2.0 * std::numbers::pi / 180.0;
inline constexpr double kPivotOutlierChiSquare = 16.266;  // χ²₃(0.999)
inline constexpr int kPivotIterations = 100;
inline constexpr int kPivotRejectionRounds = 5;

struct PivotOptions {
  // Robot pose noise per axis (radians, metres); nullopt: estimated (step 3 above).
  std::optional<PoseSigma> sigma;
  bool reject_outliers = true;  // leave flagged stations out and fit again (step 5)

  // core/options_check.h: false naming PivotOptions.sigma when out of pose_sigma.h's range or
  // when its translation is 0 (the weights of (P3) need translation noise).
  bool IsValid(std::string* why) const;
};

struct PivotStation {
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();  // e_i, metres, base frame
  double standardized = 0.0;                           // d_i with the sigma used
  bool outlier = false;                                // d_i² > kPivotOutlierChiSquare
  bool used = true;                                    // in the final fit
};

struct PivotResult {
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();            // t_tip, flange frame, metres
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();          // p, base frame, metres
  Eigen::Vector3d algebraic_tip = Eigen::Vector3d::Zero();  // the start (P2), all stations
  Eigen::Vector3d algebraic_pivot = Eigen::Vector3d::Zero();
  Matrix6d covariance = Matrix6d::Zero();  // of (t_tip, p), m², (P5)
  PoseSigma sigma;                         // the noise used (given, or estimated)
  bool sigma_estimated = false;
  double chi_square = 0.0;             // Σ d_i² over the stations used
  int dof = 0;                         // 3m − 6
  double rms = 0.0;                    // sqrt(mean |e_i|²) over the stations used, metres
  double min_tilt = 0.0;               // sqrt(λ₃) of step 6, radians
  int iterations = 0;                  // of (P4), last fit
  std::vector<PivotStation> stations;  // one per input pose
  std::vector<std::string> warnings;
};

// Steps 1–6 above. Throws InputError when !options.IsValid (RequireValid) and DegenerateError as
// in step 6.
PivotResult CalibratePivot(const std::vector<Pose>& T_base_flange, const PivotOptions& options);

}  // namespace hecal::estimation
