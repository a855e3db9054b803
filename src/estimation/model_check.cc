#include "hecal/estimation/model_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/calibration_covariance.h"
#include "hecal/geometry/dense_decompositions.h"
#include "hecal/geometry/se3.h"

namespace hecal::estimation {
namespace {

using Vector12d = Eigen::Matrix<double, 12, 1>;
using Matrix12d = Eigen::Matrix<double, 12, 12>;

constexpr const char* kAxisNames[6] = {"rx", "ry", "rz", "tx", "ty", "tz"};

// The share of the largest single group in the jackknife variance of one axis.
double LargestShare(const std::vector<Vector12d>& deviations, int axis) {
  double sum = 0.0, largest = 0.0;
  for (const Vector12d& d : deviations) {
    const double t = d(axis) * d(axis);
    sum += t;
    largest = std::max(largest, t);
  }
  return sum > 0.0 ? largest / sum : 0.0;
}

std::string Percent(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.0f%%", value * 100.0);
  return buffer;
}

std::string Ratio(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2g", value);
  return buffer;
}

}  // namespace

Vector12d ModelCheck::Ratio() const {
  Vector12d ratio;
  for (int k = 0; k < 12; ++k)
    ratio(k) = sigma_model(k) > 0.0 ? sigma_check(k) / sigma_model(k) : 0.0;
  return ratio;
}

Vector12d ModelCheck::Inflation() const {
  const Vector12d ratio = Ratio();
  Vector12d inflation = Vector12d::Ones();
  for (int k = 0; k < 12; ++k) {
    if (!(ratio(k) > 1.0)) continue;
    const double log_ratio = std::log(ratio(k));
    const double e = relative_error(k);
    inflation(k) = std::exp(std::max(0.0, log_ratio - e * e / log_ratio));
  }
  return inflation;
}

std::vector<std::vector<bool>> JackknifeGroups(size_t stations) {
  const size_t groups = std::min(stations, kModelCheckMaxGroups);
  std::vector<std::vector<bool>> kept(groups, std::vector<bool>(stations, true));
  for (size_t i = 0; i < stations; ++i) kept[i % groups][i] = false;
  return kept;
}

namespace {

// Per jackknife group g: N_g = Σ_{i∈g} J_iᵀ Σ_i⁻¹ J_i and b_g = Σ_{i∈g} J_iᵀ Σ_i⁻¹ r_i.
struct GroupTerms {
  std::vector<Matrix12d> information;
  std::vector<Vector12d> gradient;
  Matrix12d total_information = Matrix12d::Zero();
  Vector12d total_gradient = Vector12d::Zero();
};

GroupTerms SumByGroup(const std::vector<StationLinearization>& stations,
                      const NoiseVariances& variances,
                      const std::vector<std::vector<bool>>& groups) {
  const size_t G = groups.size();
  GroupTerms terms;
  terms.information.assign(G, Matrix12d::Zero());
  terms.gradient.assign(G, Vector12d::Zero());
  for (size_t i = 0; i < stations.size(); ++i) {
    size_t g = 0;
    while (g < G && groups[g][i]) ++g;  // the group that leaves station i out
    if (g == G) continue;
    const Matrix6d sigma = CombineComponents(stations[i].components, variances);
    const Eigen::Matrix<double, 12, 6> JtW =
        stations[i].jacobian.transpose() * sigma.ldlt().solve(Matrix6d::Identity());
    terms.information[g] += JtW * stations[i].jacobian;
    terms.gradient[g] += JtW * stations[i].residual;
  }
  for (size_t g = 0; g < G; ++g) {
    terms.total_information += terms.information[g];
    terms.total_gradient += terms.gradient[g];
  }
  return terms;
}

}  // namespace

Matrix12d ExpectedJackknife(const std::vector<StationLinearization>& stations,
                            const NoiseVariances& variances,
                            const std::vector<std::vector<bool>>& groups) {
  const size_t G = groups.size();
  const GroupTerms terms = SumByGroup(stations, variances, groups);
  const std::vector<Matrix12d>& information = terms.information;
  const Matrix12d& total = terms.total_information;
  const Matrix12d total_inverse = PseudoInverse12(total);
  std::vector<Matrix12d> A(G);
  for (size_t g = 0; g < G; ++g) A[g] = PseudoInverse12(total - information[g]);
  // Σ_g E[d_g d_gᵀ] − G E[d̄ d̄ᵀ] with Cov(b_g, b_h) = δ_gh N_g − N_g N⁻¹ N_h.
  Matrix12d expected = Matrix12d::Zero();
  for (size_t g = 0; g < G; ++g) {
    for (size_t h = 0; h < G; ++h) {
      Matrix12d c = -information[g] * total_inverse * information[h];
      if (g == h) c += information[g];
      expected -= A[g] * c * A[h].transpose() / static_cast<double>(G);
      if (g == h) expected += A[g] * c * A[g].transpose();
    }
  }
  return (G - 1.0) / static_cast<double>(G) * expected;
}

std::vector<handeye::Solution> LinearizedWithoutGroups(
    const std::vector<StationLinearization>& stations, const NoiseVariances& variances,
    const std::vector<std::vector<bool>>& groups, const Pose& X, const Pose& Z) {
  const GroupTerms terms = SumByGroup(stations, variances, groups);
  std::vector<handeye::Solution> solutions;
  for (size_t g = 0; g < groups.size(); ++g) {
    // J_i = ∂r_i/∂δ (loop_residual.h), so the least-squares step is −N⁻¹ b.
    const Vector12d delta = -PseudoSolve12(terms.total_information - terms.information[g],
                                           terms.total_gradient - terms.gradient[g]);
    solutions.push_back({X * se3::Exp(delta.head<6>()), Z * se3::Exp(delta.tail<6>())});
  }
  return solutions;
}

ModelCheck CompareWithJackknife(const Pose& X, const Pose& Z,
                                const std::vector<handeye::Solution>& without_group,
                                const Matrix12d& model_covariance, const Matrix12d& expected) {
  ModelCheck check;
  check.possible = true;
  check.model_covariance = model_covariance;
  const int G = static_cast<int>(without_group.size());
  check.groups = G;
  std::vector<Vector12d> deviations;
  Vector12d mean = Vector12d::Zero();
  for (const handeye::Solution& s : without_group) {
    Vector12d d;
    d << se3::Log(X.inverse() * s.X), se3::Log(Z.inverse() * s.Z);
    deviations.push_back(d);
    mean += d / G;
  }
  for (Vector12d& d : deviations) d -= mean;
  const double factor = (G - 1.0) / G;
  const double gaussian_error = std::sqrt(2.0 / (G - 1.0));
  for (int k = 0; k < 12; ++k) {
    double sum = 0.0, sum_sq = 0.0;
    for (const Vector12d& d : deviations) {
      const double t = d(k) * d(k);
      sum += t;
      sum_sq += t * t;
    }
    const double variance = factor * sum;
    const double term_mean = sum / G;
    const double term_variance = std::max(0.0, (sum_sq - G * term_mean * term_mean) / (G - 1.0));
    const double spread_error = sum > 0.0 ? std::sqrt(G * term_variance) / sum : 0.0;
    check.sigma_model(k) = std::sqrt(std::max(0.0, model_covariance(k, k)));
    check.sigma_check(k) = expected(k, k) > 0.0
                               ? check.sigma_model(k) * std::sqrt(variance / expected(k, k))
                               : std::sqrt(variance);
    check.relative_error(k) = 0.5 * std::max(gaussian_error, spread_error);
    check.flagged[static_cast<size_t>(k)] =
        k < 6 && check.sigma_check(k) >
                     check.sigma_model(k) * (1.0 + kModelCheckFlagLevel * check.relative_error(k));
    check.used = check.used || check.flagged[static_cast<size_t>(k)];
  }
  return check;
}

Matrix12d ReportedCovariance(const ModelCheck& check) {
  if (!check.used) return check.model_covariance;
  const Vector12d scale = check.Inflation();
  return scale.asDiagonal() * check.model_covariance * scale.asDiagonal();
}

void ApplyModelCheck(const handeye::Problem& problem, const CalibrateOptions& options,
                     CalibrationResult* result) {
  ModelCheck check;
  const size_t n = problem.A.size();
  check.model_covariance = result->covariance->covariance;
  if (n < kModelCheckMinStations) {
    check.reason = "with " + std::to_string(n) +
                   " stations no check of the noise model is possible (it needs at least " +
                   std::to_string(kModelCheckMinStations) + ")";
    result->warnings.push_back("the covariance trusts the noise model unchecked: " + check.reason +
                               "; add stations to have it checked");
    result->model_check = check;
    return;
  }
  const std::vector<std::vector<bool>> groups = JackknifeGroups(n);
  std::vector<StationLinearization> linearized = LinearizeStations(problem, result->X, result->Z);
  // A heavy-tailed fit's station covariances (student_t.h).
  for (size_t i = 0; i < result->station_scale.size(); ++i)
    for (Matrix6d& Q : linearized[i].components) Q *= result->station_scale[i];
  const NoiseVariances variances =
      Variances(result->robot_sigma, result->camera_sigma, result->camera_excess);
  std::vector<handeye::Solution> without_group;
  if (n > kModelCheckSolvedStations) {
    without_group = LinearizedWithoutGroups(linearized, variances, groups, result->X, result->Z);
  } else {
    try {
      for (const std::vector<bool>& kept : groups)
        without_group.push_back(
            Resolve(handeye::SubProblem(problem, kept), *result, options, kept));
    } catch (const std::exception& e) {
      check.reason = std::string("a solve without one group of stations failed: ") + e.what();
      result->warnings.push_back("the noise model could not be checked: " + check.reason);
      result->model_check = check;
      return;
    }
  }
  const Matrix12d expected = ExpectedJackknife(linearized, variances, groups);
  check =
      CompareWithJackknife(result->X, result->Z, without_group, check.model_covariance, expected);
  result->model_check = check;
  if (!check.used) return;
  result->covariance->covariance = ReportedCovariance(check);

  // The warning: the flagged axes with their ratios, and the likely cause.
  std::vector<Vector12d> deviations;
  for (const handeye::Solution& s : without_group) {
    Vector12d d;
    d << se3::Log(result->X.inverse() * s.X), se3::Log(result->Z.inverse() * s.Z);
    deviations.push_back(d);
  }
  const Vector12d ratio = check.Ratio();
  std::string axes;
  int worst_axis = 0;
  bool rotation = false, translation = false;
  for (int k = 0; k < 6; ++k) {
    if (!check.flagged[static_cast<size_t>(k)]) continue;
    if (!axes.empty()) axes += ", ";
    axes += std::string("X ") + kAxisNames[k] + " " + Ratio(ratio(k)) + "x";
    if (ratio(k) > ratio(worst_axis) || !check.flagged[static_cast<size_t>(worst_axis)])
      worst_axis = k;
    (k < 3 ? rotation : translation) = true;
  }
  std::string cause;
  const double share = LargestShare(deviations, worst_axis);
  if (share > 0.5) {
    int station = 0;
    for (int g = 0; g < check.groups; ++g) {
      if (std::abs(deviations[static_cast<size_t>(g)](worst_axis)) >
          std::abs(deviations[static_cast<size_t>(station)](worst_axis)))
        station = g;
    }
    const std::string id = n <= kModelCheckMaxGroups
                               ? (static_cast<size_t>(station) < options.station_ids.size()
                                      ? options.station_ids[static_cast<size_t>(station)]
                                      : std::to_string(station + 1))
                               : "group " + std::to_string(station + 1);
    cause = "one station dominates (" + Percent(share) + " of the spread without station " + id +
            "): an outlier the 3-sigma test did not reject, or the only station that fixes that "
            "axis";
  } else if (result->sigmas_estimated) {
    cause =
        std::string("the noise is not what the estimated model assumes: anisotropic (e.g. a ") +
        "camera pose whose depth and tilt are less precise than the rest), not split " +
        "equally between robot and camera, or heavy-tailed" +
        (rotation != translation
             ? "; only " + std::string(rotation ? "rotation" : "translation") + " axes are affected"
             : std::string());
  } else {
    cause =
        "the given --robot-sigma / --camera-sigma are too small for these data, or the noise "
        "is anisotropic or heavy-tailed";
  }
  result->warnings.push_back(
      "the noise model understates the uncertainty: a jackknife over " +
      std::to_string(check.groups) + " station groups gives larger sigmas on " + axes +
      " (beyond its own sampling error); the reported covariance takes them per axis, shrunk "
      "towards the model's by that error (covariance.model_check). Likely cause: " +
      cause +
      (n < 12 ? "; with only " + std::to_string(n) +
                    " stations the check itself is uncertain to about " +
                    Percent(check.relative_error(worst_axis)) + " in sigma"
              : std::string()));
}

}  // namespace hecal::estimation
