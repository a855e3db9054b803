#include "hecal/estimation/student_t.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace hecal::estimation {
namespace {

constexpr int kMaxScaleIterations = 200;
constexpr double kScaleTolerance = 1e-10;  // relative change of c

// Σ_i ℓ_i at scale c, without the −½ Σ log det S_i both models share.
double LogLikelihood(const std::vector<double>& q, double dof, int d, double c) {
  const double n = static_cast<double>(q.size());
  double sum = n * (std::lgamma(0.5 * (dof + d)) - std::lgamma(0.5 * dof) -
                    0.5 * d * std::log(dof * std::numbers::pi * c));
  for (double q_i : q) sum -= 0.5 * (dof + d) * std::log1p(q_i / (dof * c));
  return sum;
}

}  // namespace

double StudentTWeight(double q, double dof, int dimension) {
  return (dof + dimension) / (dof + q);
}

double StudentTInformationFactor(double dof, int dimension) {
  return (dof + dimension + 2.0) / (dof + dimension);
}

StudentTChoice ChooseStudentT(const std::vector<double>& q, int dimension) {
  if (q.empty()) throw std::invalid_argument("ChooseStudentT: no stations");
  double sum = 0.0;
  for (double q_i : q) {
    if (!(q_i >= 0.0) || !std::isfinite(q_i))
      throw std::invalid_argument("ChooseStudentT: distances must be finite and non-negative");
    sum += q_i;
  }
  const double nd = static_cast<double>(q.size()) * dimension;
  StudentTChoice choice;
  if (!(sum > 0.0)) return choice;  // noise-free: nothing to tell
  const double gaussian_scale = sum / nd;
  const double gaussian = -0.5 * nd * (std::log(2.0 * std::numbers::pi * gaussian_scale) + 1.0);
  double best = -std::numeric_limits<double>::infinity();
  for (double dof : kStudentTDof) {
    double c = gaussian_scale;
    for (int iteration = 0; iteration < kMaxScaleIterations; ++iteration) {
      double weighted = 0.0;
      for (double q_i : q) weighted += StudentTWeight(q_i / c, dof, dimension) * q_i;
      const double next = weighted / nd;
      const bool done = std::abs(next - c) <= kScaleTolerance * c;
      c = next;
      if (done) break;
    }
    const double likelihood = LogLikelihood(q, dof, dimension, c);
    if (likelihood > best) {
      best = likelihood;
      choice.dof = dof;
      choice.scale = c;
    }
  }
  choice.likelihood_ratio = std::max(0.0, 2.0 * (best - gaussian));
  choice.chosen = choice.likelihood_ratio > kStudentTThreshold;
  return choice;
}

}  // namespace hecal::estimation
