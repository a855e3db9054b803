#include "hecal/uncertainty/monte_carlo.h"

#include <random>

#include "hecal/core/limits.h"
#include "hecal/core/random_draws.h"
#include "hecal/core/split_mix.h"

namespace hecal::uncertainty {

bool MonteCarloOptions::IsValid(std::string* why) const {
  if (samples < 2) {
    return Invalid(why, "MonteCarloOptions.samples",
                   "Monte Carlo needs at least 2 samples, got " + std::to_string(samples),
                   "use e.g. 5000");
  }
  if (!ThreadCountValid(threads, "MonteCarloOptions.threads", why)) return false;
  return true;
}

Eigen::VectorXd StandardNormalSample(std::uint64_t seed, int k, int n) {
  std::mt19937_64 rng(SplitMix64(SplitMix64(seed) ^ static_cast<std::uint64_t>(k)));
  hecal::NormalDistribution normal(0.0, 1.0);
  Eigen::VectorXd z(n);
  for (int j = 0; j < n; ++j) z(j) = normal(rng);
  return z;
}

void SampleStatistics(const Eigen::MatrixXd& deviations, Eigen::MatrixXd* covariance,
                      Eigen::VectorXd* mean_std_error, Eigen::VectorXd* sd_std_error) {
  const auto m = static_cast<double>(deviations.rows());
  if (deviations.rows() < 2) throw std::invalid_argument("sample statistics: needs 2 samples");
  const Eigen::MatrixXd centred = deviations.rowwise() - deviations.colwise().mean();
  *covariance = centred.transpose() * centred / (m - 1.0);
  const Eigen::VectorXd variance = covariance->diagonal();
  *mean_std_error = (variance / m).cwiseSqrt();
  const Eigen::VectorXd m4 = centred.array().pow(4).colwise().mean().transpose();
  sd_std_error->resize(variance.size());
  for (Eigen::Index j = 0; j < variance.size(); ++j) {
    const double s = std::sqrt(variance(j));
    const double var_of_variance = std::max(m4(j) - variance(j) * variance(j), 0.0) / m;
    (*sd_std_error)(j) = s > 0.0 ? std::sqrt(var_of_variance) / (2.0 * s) : 0.0;
  }
}

}  // namespace hecal::uncertainty
