#include "hecal/uncertainty/consistency.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unsupported/Eigen/SpecialFunctions>

namespace hecal::uncertainty {

double ChiSquareCdf(double x, double dof) {
  if (!(dof > 0.0)) throw std::invalid_argument("ChiSquareCdf: dof must be positive");
  if (!(x > 0.0)) return 0.0;
  if (std::isinf(x)) return 1.0;
  return Eigen::numext::igamma(0.5 * dof, 0.5 * x);
}

namespace {

// x ≥ 0 with cdf(x) = p for an increasing cdf on [0, ∞): bracketing, then bisection.
template <typename Cdf>
double Quantile(const Cdf& cdf, double p, double start) {
  double low = 0.0, high = std::max(1.0, start);
  while (cdf(high) < p) high *= 2.0;
  for (int i = 0; i < 200 && high - low > 1e-12 * high; ++i) {
    const double mid = 0.5 * (low + high);
    (cdf(mid) < p ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace

double ChiSquareQuantile(double p, double dof) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("ChiSquareQuantile: p must be in (0, 1)");
  if (!(dof > 0.0)) throw std::invalid_argument("ChiSquareQuantile: dof must be positive");
  return Quantile([dof](double x) { return ChiSquareCdf(x, dof); }, p, dof);
}

double FisherCdf(double x, double d1, double d2) {
  if (!(d1 > 0.0 && d2 > 0.0)) throw std::invalid_argument("FisherCdf: dof must be positive");
  if (!(x > 0.0)) return 0.0;
  if (std::isinf(x)) return 1.0;
  return Eigen::numext::betainc(0.5 * d1, 0.5 * d2, d1 * x / (d1 * x + d2));
}

double FisherQuantile(double p, double d1, double d2) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("FisherQuantile: p must be in (0, 1)");
  if (!(d1 > 0.0 && d2 > 0.0)) throw std::invalid_argument("FisherQuantile: dof must be positive");
  return Quantile([d1, d2](double x) { return FisherCdf(x, d1, d2); }, p, 1.0);
}

double SigmaProbability(double k) {
  return std::erf(k / std::sqrt(2.0));
}

double Nees(const Eigen::VectorXd& error, const Eigen::MatrixXd& covariance) {
  const Eigen::LLT<Eigen::MatrixXd> llt(covariance);
  if (llt.info() != Eigen::Success || !error.allFinite()) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return error.dot(llt.solve(error));
}

Interval MeanNeesBand(int dof, int trials, double confidence) {
  if (dof < 1 || trials < 1 || !(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument("MeanNeesBand: needs dof, trials >= 1 and confidence in (0, 1)");
  }
  const double total = static_cast<double>(dof) * trials;
  const double tail = 0.5 * (1.0 - confidence);
  return {ChiSquareQuantile(tail, total) / trials, ChiSquareQuantile(1.0 - tail, total) / trials};
}

Consistency AssessConsistency(std::span<const Eigen::VectorXd> errors,
                              std::span<const Eigen::MatrixXd> covariances) {
  if (errors.size() != covariances.size() || errors.empty()) {
    throw std::invalid_argument("AssessConsistency: needs one covariance per error, at least one");
  }
  Consistency result;
  result.dof = static_cast<int>(errors[0].size());
  const double limit1 = ChiSquareQuantile(SigmaProbability(1.0), result.dof);
  const double limit2 = ChiSquareQuantile(SigmaProbability(2.0), result.dof);
  Eigen::VectorXd predicted = Eigen::VectorXd::Zero(result.dof);
  Eigen::VectorXd empirical = Eigen::VectorXd::Zero(result.dof);
  double sum = 0.0;
  int inside1 = 0, inside2 = 0;
  for (size_t t = 0; t < errors.size(); ++t) {
    const double nees = Nees(errors[t], covariances[t]);
    if (!std::isfinite(nees)) continue;
    ++result.trials;
    sum += nees;
    inside1 += nees <= limit1 ? 1 : 0;
    inside2 += nees <= limit2 ? 1 : 0;
    predicted += covariances[t].diagonal();
    empirical += errors[t].cwiseAbs2();
  }
  if (result.trials == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    result.mean_nees = result.coverage_1sigma = result.coverage_2sigma = nan;
    result.band = {nan, nan};
    result.sd_ratio = Eigen::VectorXd::Constant(result.dof, nan);
    return result;
  }
  const double n = result.trials;
  result.mean_nees = sum / n;
  result.band = MeanNeesBand(result.dof, result.trials);
  result.coverage_1sigma = inside1 / n;
  result.coverage_2sigma = inside2 / n;
  result.sd_ratio = predicted.cwiseQuotient(empirical).cwiseSqrt();
  return result;
}

Eigen::VectorXd StdRatio(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  if (a.rows() != b.rows()) throw std::invalid_argument("StdRatio: sizes differ");
  return a.diagonal().cwiseQuotient(b.diagonal()).cwiseSqrt();
}

}  // namespace hecal::uncertainty
