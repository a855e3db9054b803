// Monte Carlo transform: the mean and covariance of y = f(x), x = x̄ ⊞ δ, δ ~ N(0, Σx), from N
// random samples — the ground truth the contour paper checks the Unscented Transform against
// (docs/contour.md#the-experiments: 5000 samples).
//
// Sample k draws δ_k = S z_k, z_k ~ N(0, I) (S the square root of unscented.h), from a
// std::mt19937_64 seeded with SplitMix64(seed, k): the same seed gives the same samples and
// results whatever the number of threads.
// Statistics over the M samples that succeeded (f returned without throwing std::exception and
// y ⊟ f(x̄) is finite): the mean on the manifold (manifold.h, started from f(x̄)),
// the covariance Σ (y_k ⊟ ȳ)(y_k ⊟ ȳ)ᵀ / (M − 1), and their own sampling errors per axis:
//   standard error of the mean:  sqrt(Σy_jj / M)
//   standard error of the standard deviation s_j:  sqrt((m4_j − s_j⁴) / M) / (2 s_j)
//   (m4_j the fourth central moment; the delta method, no Gaussian assumption on y).
// Failed samples are counted and the first failure's message kept; they are not silently
// replaced, so a caller can tell when f fails on part of the input distribution.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/uncertainty/manifold.h"
#include "hecal/uncertainty/parallel_for.h"
#include "hecal/uncertainty/unscented.h"

namespace hecal::uncertainty {

struct MonteCarloOptions {
  int samples = 5000;  // at least 2
  std::uint64_t seed = 1;
  int threads = 0;  // 0: every core, at most kMaxThreads (core/limits.h)
  SquareRoot square_root = SquareRoot::kCholesky;

  // core/options_check.h: false naming MonteCarloOptions.samples (below 2) or .threads (outside
  // 0 … kMaxThreads).
  bool IsValid(std::string* why) const;
};

template <class Out>
struct MonteCarloMoments {
  Out mean;
  Eigen::MatrixXd covariance;
  Eigen::VectorXd mean_std_error;  // per axis, tangent units
  Eigen::VectorXd sd_std_error;    // per axis, of sqrt(covariance(j, j))
  int samples = 0;                 // that succeeded
  int failures = 0;
  std::string first_failure;  // what() of the first failed sample (lowest index)
};

// z ~ N(0, I_n) for sample k of `seed` (deterministic, see above).
Eigen::VectorXd StandardNormalSample(std::uint64_t seed, int k, int n);

// Sample statistics of tangent vectors d_k = y_k ⊟ ȳ (rows: samples) — the covariance and the
// two standard errors above. Needs at least 2 rows.
void SampleStatistics(const Eigen::MatrixXd& deviations, Eigen::MatrixXd* covariance,
                      Eigen::VectorXd* mean_std_error, Eigen::VectorXd* sd_std_error);

// The statistics above over y_k = sample(k), k = 0 … samples − 1, for callers that draw their
// own inputs (e.g. a diagonal noise model too large for a dense covariance): sample(k) should
// use StandardNormalSample(options.seed, k, n) so that the result does not depend on the number
// of threads. `reference` (the unperturbed output) starts the mean and screens non-finite
// results. Throws hecal::InputError when !options.IsValid, hecal::DegenerateError when fewer than
// 2 samples succeed.
template <class Out, class Sample>
MonteCarloMoments<Out> MonteCarloSamples(const Sample& sample, const Out& reference,
                                         const MonteCarloOptions& options) {
  using MOut = Manifold<Out>;
  RequireValid(options);
  const size_t count = static_cast<size_t>(options.samples);
  std::vector<Out> y(count, reference);
  std::vector<char> ok(count, 0);
  std::vector<std::string> failure(count);
  ParallelFor(options.samples, options.threads, [&](int k) {
    const size_t i = static_cast<size_t>(k);
    try {
      y[i] = sample(k);
      if (MOut::Minus(y[i], reference).allFinite()) {
        ok[i] = 1;
      } else {
        failure[i] = "non-finite result";
      }
    } catch (const std::exception& e) {
      failure[i] = e.what();
    }
  });
  MonteCarloMoments<Out> moments;
  std::vector<Out> good;
  good.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    if (ok[i]) {
      good.push_back(std::move(y[i]));
    } else if (moments.failures++ == 0) {
      moments.first_failure = failure[i];
    }
  }
  moments.samples = static_cast<int>(good.size());
  if (moments.samples < 2) {
    throw DegenerateError("the spread of the estimate by Monte Carlo: " +
                              std::to_string(moments.samples) + " of " + std::to_string(count) +
                              " samples could be solved (first failure: " +
                              moments.first_failure + ")",
                          "lower the noise the samples are drawn with, or use a linear or "
                          "unscented covariance");
  }
  const std::vector<double> weights(good.size(), 1.0 / static_cast<double>(good.size()));
  moments.mean = WeightedMean<Out>(good, weights, reference);
  Eigen::MatrixXd deviations(moments.samples, MOut::Dim(moments.mean));
  for (size_t i = 0; i < good.size(); ++i) {
    deviations.row(static_cast<Eigen::Index>(i)) = MOut::Minus(good[i], moments.mean).transpose();
  }
  SampleStatistics(deviations, &moments.covariance, &moments.mean_std_error, &moments.sd_std_error);
  return moments;
}

// Throws hecal::InputError for samples < 2, std::invalid_argument for a covariance of the wrong
// size, DegenerateError when fewer than 2 samples succeed, and what f(x̄) itself throws.
template <class In, class Out, class F>
MonteCarloMoments<Out> MonteCarloTransform(const F& f, const In& mean,
                                           const Eigen::MatrixXd& covariance,
                                           const MonteCarloOptions& options = {}) {
  using MIn = Manifold<In>;
  const int n = MIn::Dim(mean);
  if (covariance.rows() != n || covariance.cols() != n) {
    throw std::invalid_argument("Monte Carlo: the covariance is not dim × dim");
  }
  const Eigen::MatrixXd S = CovarianceSquareRoot(covariance, options.square_root);
  return MonteCarloSamples<Out>(
      [&](int k) { return f(MIn::Plus(mean, S * StandardNormalSample(options.seed, k, n))); },
      f(mean), options);
}

}  // namespace hecal::uncertainty
