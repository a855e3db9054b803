// The Unscented Transform (Julier and Uhlmann, "A new extension of the Kalman filter to
// nonlinear systems", 1997; docs/uncertainty.md#the-unscented-transform): the mean and covariance
// of y = f(x) for x with mean x̄ and covariance Σx, from f at 2n + 1 deterministic sigma points.
//
// Sigma points (n = dim x; S a square root of Σx, Σx = S Sᵀ; S_i its i-th COLUMN):
//   x_0 = x̄,   x_i = x̄ ⊞ (+c S_i),   x_{n+i} = x̄ ⊞ (−c S_i),   i = 1..n
//   ȳ = Σ w_i^m y_i (on a manifold: the iterative weighted mean of manifold.h, from y_0),
//   Σy = Σ w_i^c (y_i ⊟ ȳ)(y_i ⊟ ȳ)ᵀ.
// Two parameter forms:
//  - kSymmetric, the contour paper's own (docs/uncertainty.md#the-unscented-transform): c = sqrt(n
//    / (1 − w0)), w_0 = w0 and w_i = (1 − w0)/(2n) for both mean and covariance. w0 < 1. Default w0
//    = 1 − n/3, Julier and Uhlmann's choice for Gaussian inputs: c = √3, the points sit at ±√3 σ
//    along each column, which matches the fourth moment of each axis (so the transform is exact for
//    quadratics of a single axis). For n > 3 the centre weight is negative; the mean and covariance
//    stay correct, and the points stay near the data (c = √3 whatever n), which is what nonlinear
//    estimators such as hand–eye solvers need when n is in the hundreds.
//  - kScaled (Julier, "The scaled unscented transformation", ACC 2002): λ = α²(n + κ) − n,
//    c = sqrt(n + λ), w_0^m = λ/(n + λ), w_0^c = w_0^m + 1 − α² + β, w_i = 1/(2(n + λ)).
//    Needs α > 0 and n + κ > 0.
// In both the mean weights sum to 1, and the points reproduce x̄ and Σx exactly, so the transform
// is exact (mean and covariance) for linear maps.
// Negative centre weight (w_0^c < 0, e.g. the default symmetric set for n > 3): the covariance
// Σ w_i^c (y_i ⊟ ȳ)(…)ᵀ can then be indefinite for a strongly nonlinear f (seen with Daniilidis'
// solver: 12 of 200 thesis-protocol data sets at σ = 1 mm / 1°). hecal then uses Julier and
// Uhlmann's modified form (1997, §IV): the covariance about the transformed centre point,
//   Σy = Σ_{i≥1} w_i (y_i ⊟ y_0)(y_i ⊟ y_0)ᵀ,
// positive semidefinite by construction, equal to the standard form plus (ȳ ⊟ y_0)(ȳ ⊟ y_0)ᵀ
// (the squared second-order bias; zero for linear maps, so exactness for them is kept). For an
// estimator, y_0 = f(x̄) is the estimate itself, so this is the mean squared error about it.
//
// Square root: Cholesky (Σx = L Lᵀ, L lower triangular; its columns are the S_i — the contour
// paper's remark that rows or columns depend on the factorisation). Cholesky is the default because
// it is the cheapest and, for the block-diagonal input covariances of a calibration, each column
// perturbs one measurement only. A semidefinite Σx (e.g. a noise-free device) has no Cholesky
// factor: then the symmetric root V D^½ Vᵀ is used (kSymmetric asks for it always). Zero columns
// (directions without noise) give y_i = y_0 and f is not evaluated for them.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/uncertainty/manifold.h"
#include "hecal/uncertainty/parallel_for.h"

namespace hecal::uncertainty {

enum class SquareRoot { kCholesky, kSymmetric };

// S with S Sᵀ = Σ (see above). Throws std::invalid_argument when Σ is not square, not finite,
// not symmetric (relative 1e-9) or has an eigenvalue below −1e-12 of the largest.
Eigen::MatrixXd CovarianceSquareRoot(const Eigen::MatrixXd& covariance, SquareRoot kind);

// The indices of the non-zero columns of a square root: the directions with noise, the only ones
// the transforms evaluate f along.
std::vector<int> NonZeroColumns(const Eigen::MatrixXd& square_root);

struct UnscentedParameters {
  enum class Form { kSymmetric, kScaled };
  Form form = Form::kSymmetric;
  std::optional<double> w0;  // kSymmetric; nullopt: 1 − n/3
  double alpha = 1.0;        // kScaled
  double beta = 2.0;         // kScaled (2 is optimal for Gaussian inputs)
  double kappa = 0.0;        // kScaled
  SquareRoot square_root = SquareRoot::kCholesky;

  static UnscentedParameters Symmetric(std::optional<double> w0 = std::nullopt);
  static UnscentedParameters Scaled(double alpha, double beta, double kappa);
  // False (and why) when the parameters give no valid point set for dimension n.
  bool IsValid(int n, std::string* why) const;
};

struct SigmaWeights {
  double spread = 0.0;       // c: the points are x̄ ⊞ ±c S_i
  double mean_centre = 0.0;  // w_0^m
  double cov_centre = 0.0;   // w_0^c
  double other = 0.0;        // w_i, i ≥ 1 (mean and covariance)
};
// Throws hecal::InputError (source "UnscentedParameters") when !parameters.IsValid(n).
SigmaWeights Weights(int n, const UnscentedParameters& parameters);

// Mean and covariance of a transformed distribution: the covariance in the tangent space at the
// mean (manifold.h), or at f(x̄) for the UT's modified form (above).
template <class Out>
struct Moments {
  Out mean;
  Eigen::MatrixXd covariance;
  int evaluations = 0;  // calls of f
};

// The Unscented Transform of f: In → Out for x ~ (mean, covariance) with covariance on In's
// tangent space. f is called from up to `threads` threads at once (0: every core), so it must
// be safe to call concurrently. Exceptions from f propagate (every sigma point is needed).
template <class In, class Out, class F>
Moments<Out> UnscentedTransform(const F& f, const In& mean, const Eigen::MatrixXd& covariance,
                                const UnscentedParameters& parameters = {}, int threads = 1) {
  using MIn = Manifold<In>;
  const int n = MIn::Dim(mean);
  if (covariance.rows() != n || covariance.cols() != n) {
    throw std::invalid_argument("UnscentedTransform: the covariance is not dim × dim");
  }
  const SigmaWeights w = Weights(n, parameters);
  const Eigen::MatrixXd S = CovarianceSquareRoot(covariance, parameters.square_root);
  const std::vector<int> columns = NonZeroColumns(S);
  // Every point starts as y_0: for zero columns x_i = x̄, so f is not evaluated again.
  std::vector<Out> y(2 * static_cast<size_t>(n) + 1, f(mean));
  ParallelFor(2 * static_cast<int>(columns.size()), threads, [&](int job) {
    const int i = columns[static_cast<size_t>(job / 2)];
    const double sign = job % 2 == 0 ? 1.0 : -1.0;
    const Eigen::VectorXd delta = sign * w.spread * S.col(i);
    y[1 + static_cast<size_t>(job % 2 == 0 ? i : n + i)] = f(MIn::Plus(mean, delta));
  });
  std::vector<double> mean_weights(y.size(), w.other), cov_weights(y.size(), w.other);
  mean_weights[0] = w.mean_centre;
  cov_weights[0] = w.cov_centre;
  Moments<Out> moments;
  moments.mean = WeightedMean<Out>(y, mean_weights, y[0]);
  if (w.cov_centre < 0.0) {  // the modified form (above)
    cov_weights[0] = 0.0;
    moments.covariance = WeightedCovariance<Out>(y, cov_weights, y[0]);
  } else {
    moments.covariance = WeightedCovariance<Out>(y, cov_weights, moments.mean);
  }
  moments.evaluations = 1 + 2 * static_cast<int>(columns.size());
  return moments;
}

}  // namespace hecal::uncertainty
