// Heavy-tailed station noise: the multivariate Student-t model of the station residuals, its
// degrees of freedom by profile likelihood, and the test against the Gaussian model.
//
// Model. Station i's residual r_i ∈ R^d (d = 6, loop_residual.h) is a Gaussian scale mixture
// (Lange, Little & Taylor, "Robust statistical modeling using the t distribution", JASA 84, 1989,
// §2):  r_i | u_i ~ N(0, S_i / u_i),  u_i ~ Gamma(ν/2, ν/2),  so r_i ~ t_d(0, S_i, ν): a
// multivariate t with ν degrees of freedom whose scale matrix S_i = Σ_k θ_k Q_ik has the variance
// components of noise_estimation.h (Cov r_i = ν/(ν − 2) S_i for ν > 2). One latent scale per
// station: a station whose robot or camera pose is off by more than the Gaussian tail allows is
// down-weighted as a whole. With q_i = r_iᵀ S_i⁻¹ r_i the log-density is
//   ℓ_i = log Γ((ν + d)/2) − log Γ(ν/2) − (d/2) log(νπ) − ½ log det S_i − ((ν + d)/2) log(1 +
//   q_i/ν)
// and the EM step's expected latent scale (the station weight, Lange et al. eq. 3) is
//        w_i = E[u_i | r_i] = (ν + d) / (ν + q_i).
// Given the weights, the M-step is the Gaussian problem with station covariances S_i / w_i: ml's
// weighted least squares (the hand-written Levenberg–Marquardt takes the weights in its
// whitening) and the REML variance components of noise_estimation.h on components Q_ik / w_i.
//
// Choice of ν (ChooseStudentT). Profile likelihood on the grid kStudentTDof, ν = 2 … 30 (Lange
// et al. §4 and Liu & Rubin, "ML estimation of the t distribution using EM and its extensions,
// ECM and ECME", Statistica Sinica 5, 1995: ν estimated by maximising the likelihood over it; a
// small grid is enough because the likelihood is flat in ν at these sample sizes). At each ν the
// common scale c of the S_i (S_i → c S_i) is profiled out by the EM fixed point
// c ← Σ w_i q_i / (n d), w_i = (ν + d)/(ν + q_i / c), monotone in the likelihood; the Gaussian
// model gets its own maximum, c = Σ q_i / (n d). The q_i are taken at the Gaussian fit's (X, Z)
// and variance shape (the t fit would move them a little and raise ℓ_t, so the test is
// conservative). Test: the Gaussian is the boundary ν = ∞ of the t family, so the likelihood-ratio
// statistic 2 (max_ν ℓ_t − ℓ_G) has the null distribution ½ χ²₀ + ½ χ²₁ (Self & Liang, "Asymptotic
// properties of maximum likelihood estimators and likelihood ratio tests under nonstandard
// conditions", JASA 82, 1987, case 5); at 5% the threshold is the χ²₁ 90% quantile, 2.706
// (kStudentTThreshold). Measured on distances drawn exactly from the models (1000 sets each,
// student_t_test.cc): Gaussian sets of 8, 15 and 40 stations choose the t model in 1.9%, 2.0%
// and 1.7% — fewer than 5%, because the grid ends at ν = 30 — and t(3) sets in 66%, 90%, 100%.
//
// Covariance. The Fisher information of the location of a t_d(0, S, ν) observation is
// (ν + d)/(ν + d + 2) S⁻¹ (Lange et al. 1989, appendix): the weights' own randomness costs
// information that the EM's plug-in Σ w_i Jᵢᵀ S_i⁻¹ J_i does not see (E[w_i] = 1; the missing
// information of Louis, JRSS B 44, 1982). So the station covariance a t fit hands downstream is
//        Σ_i = κ_ν S_i / w_i,   κ_ν = (ν + d + 2)/(ν + d)   (StudentTInformationFactor)
// — ml's covariance, the model check's expected jackknife and the propagated covariances all use
// it; its inverse summed over the stations is the expected information on average over the
// weights, and keeps the observed down-weighting of a wild station. κ_ν is 11/9 at ν = 3.
//
// What is an outlier under it. The flags stay those of the Gaussian test (noise_estimation.h):
// a station beyond the 3σ level of the Gaussian model is reported as before, and the t fit
// down-weights it instead of trusting it fully. Judging it against the t model's own tail
// (q_i / d ~ F(d, ν)) would be circular: a single station 10σ off is what makes the t model win
// (ν = 4 on 20 stations, student_t_test.cc), and inside that tail it was not flagged (statistic
// 178 against the 3σ level 182 of 6 F(6, 4)). The outlier rejection of station_selection.h stays
// Gaussian too (it runs before, with the F test of an estimated scale); the t model is fitted on
// the stations it keeps. Tried only when neither sigma is given (ml.h): a station's latent scale
// multiplies its whole covariance, and a given sigma would be rescaled with it.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace hecal::estimation {

// The grid of ν for the profile likelihood (header).
inline constexpr std::array<double, 6> kStudentTDof = {2.0, 3.0, 4.0, 6.0, 10.0, 30.0};
// ½ χ²₀ + ½ χ²₁ at 5%: the χ²₁ quantile at 90%.
inline constexpr double kStudentTThreshold = 2.705543454095404;
// Fewest stations at which the t model is tried (the richer noise models' minimum, 36 residual
// degrees of freedom).
inline constexpr std::size_t kStudentTMinStations = 8;

struct StudentTChoice {
  bool chosen = false;            // the likelihood-ratio test prefers the t model
  double dof = 0.0;               // ν of the profile maximum (also when not chosen)
  double scale = 1.0;             // c at that ν: the t scale matrices are c S_i
  double likelihood_ratio = 0.0;  // 2 (ℓ_t(ν, c) − ℓ_G)
};

// w = (ν + d) / (ν + q).
double StudentTWeight(double q, double dof, int dimension);

// κ_ν = (ν + d + 2) / (ν + d).
double StudentTInformationFactor(double dof, int dimension);

// The profile-likelihood choice above from the squared Mahalanobis distances q_i = r_iᵀ S_i⁻¹ r_i
// of the stations under the Gaussian fit (d = `dimension` each). Throws std::invalid_argument when
// q is empty or has a negative or non-finite entry.
StudentTChoice ChooseStudentT(const std::vector<double>& q, int dimension);

}  // namespace hecal::estimation
