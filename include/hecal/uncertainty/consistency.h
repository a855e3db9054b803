// Consistency of a predicted covariance with actual errors (Bar-Shalom, Li and Kirubarajan,
// "Estimation with Applications to Tracking and Navigation", 2001, §5.4): NEES, its χ² band,
// coverage of the 1σ/2σ ellipsoids, predicted-vs-empirical standard deviation per axis, and the
// per-axis comparison of two covariances (UT vs Monte Carlo).
//
//  - NEES of one trial: ε = eᵀ Σ⁻¹ e for the error e (tangent space, e.g. X_true ⊟ X̂) and the
//    predicted covariance Σ; ε ~ χ²(d) when Σ is right and the error Gaussian.
//  - Mean NEES over N trials: N·ε̄ ~ χ²(N d), so the two-sided 95% band for ε̄ is
//    [χ²⁻¹(0.025; N d), χ²⁻¹(0.975; N d)] / N (for d = 6, N = 200: [5.53, 6.50]).
//  - Coverage of the kσ ellipsoid: the fraction of trials with ε ≤ χ²⁻¹(P_k; d), where
//    P_k = erf(k/√2) is the 1-D probability within ±kσ (68.27%, 95.45%), so a consistent
//    covariance covers 68.27% / 95.45% of the trials whatever d.
//  - Standard deviation ratio per axis j: sqrt(mean_t Σ_t,jj) / sqrt(mean_t e_t,j²) — predicted
//    over empirical RMS; > 1 is pessimistic, < 1 optimistic.
// χ² from the regularised incomplete gamma function P(d/2, x/2) (Eigen's SpecialFunctions), its
// quantile by bracketing and bisection to 1e-12 relative. Fisher's F(d1, d2) (the ratio of two
// independent χ² over their degrees of freedom; the distribution of a test statistic whose scale
// is estimated from d2 degrees of freedom) from the regularised incomplete beta function
// I_{d1 x / (d1 x + d2)}(d1/2, d2/2), its quantile the same way.
#pragma once

#include <Eigen/Core>
#include <span>

namespace hecal::uncertainty {

// P(X ≤ x) for X ~ χ²(dof), dof > 0.
double ChiSquareCdf(double x, double dof);
// x with ChiSquareCdf(x, dof) = p, p in (0, 1).
double ChiSquareQuantile(double p, double dof);
// P(X ≤ x) for X ~ F(d1, d2), d1, d2 > 0.
double FisherCdf(double x, double d1, double d2);
// x with FisherCdf(x, d1, d2) = p, p in (0, 1).
double FisherQuantile(double p, double d1, double d2);
// erf(k/√2): the probability within ±k standard deviations of a 1-D Gaussian.
double SigmaProbability(double k);

// eᵀ Σ⁻¹ e; NaN when Σ is not positive definite.
double Nees(const Eigen::VectorXd& error, const Eigen::MatrixXd& covariance);

struct Interval {
  double low = 0.0;
  double high = 0.0;
  bool Contains(double x) const { return x >= low && x <= high; }
};
// The band of the mean NEES (above) at two-sided `confidence`.
Interval MeanNeesBand(int dof, int trials, double confidence = 0.95);

struct Consistency {
  int trials = 0;  // with a finite NEES (a singular covariance is left out)
  int dof = 0;
  double mean_nees = 0.0;
  Interval band;                 // 95% band for mean_nees
  double coverage_1sigma = 0.0;  // fractions in [0, 1]
  double coverage_2sigma = 0.0;
  Eigen::VectorXd sd_ratio;  // per axis, predicted / empirical
};

// errors[t] and covariances[t] of trial t (same dimension d for every trial).
Consistency AssessConsistency(std::span<const Eigen::VectorXd> errors,
                              std::span<const Eigen::MatrixXd> covariances);

// sqrt(a_jj / b_jj) per axis: e.g. UT over Monte Carlo standard deviations.
Eigen::VectorXd StdRatio(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

}  // namespace hecal::uncertainty
