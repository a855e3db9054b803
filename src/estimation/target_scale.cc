// The target's scale as an unknown: see target_scale.h.
#include "hecal/estimation/target_scale.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "hecal/estimation/loop_residual.h"
#include "hecal/estimation/model_check.h"
#include "hecal/estimation/station_covariance.h"
#include "hecal/geometry/se3.h"

namespace hecal::estimation {
namespace {

using Matrix13d = Eigen::Matrix<double, 13, 13>;
using Vector13d = Eigen::Matrix<double, 13, 1>;

struct State {
  Pose X;
  Pose Z;
  double log_scale = 0.0;
};

// One station's whitened residual and Jacobian over (δX, δZ, ε).
struct StationTerms {
  Vector6d residual;
  Eigen::Matrix<double, 6, 13> jacobian;
};

StationTerms LinearizeScaled(const Pose& A, const Pose& B, const Matrix6d& whitening,
                             const State& state) {
  Pose scaled = B;
  scaled.translation() *= std::exp(state.log_scale);
  Matrix6x12d pose_jacobian;
  const Vector6d r = LoopResidual(A, scaled, state.X, state.Z, &pose_jacobian);
  Vector6d xi = Vector6d::Zero();
  xi.tail<3>() = scaled.linear().transpose() * scaled.translation();
  StationTerms terms;
  terms.residual = whitening * r;
  terms.jacobian.leftCols<12>() = whitening * pose_jacobian;
  terms.jacobian.col(12) = whitening * (se3::RightJacobianInverse(r) * xi);
  return terms;
}

struct Normal {
  Matrix13d information = Matrix13d::Zero();
  Vector13d gradient = Vector13d::Zero();
  double cost = 0.0;
  std::vector<Matrix13d> group_information;
  std::vector<Vector13d> group_gradient;
};

// Σ Jᵀ J, Σ Jᵀ r and Σ |r|² over the stations, and per jackknife group (the group that leaves
// station i out, model_check.h's JackknifeGroups).
Normal Accumulate(const handeye::Problem& problem, const std::vector<Matrix6d>& whitening,
                  const State& state, const std::vector<std::vector<bool>>& groups) {
  Normal normal;
  normal.group_information.assign(groups.size(), Matrix13d::Zero());
  normal.group_gradient.assign(groups.size(), Vector13d::Zero());
  for (size_t i = 0; i < problem.A.size(); ++i) {
    const StationTerms terms = LinearizeScaled(problem.A[i], problem.B[i], whitening[i], state);
    const Matrix13d information = terms.jacobian.transpose() * terms.jacobian;
    const Vector13d gradient = terms.jacobian.transpose() * terms.residual;
    normal.information += information;
    normal.gradient += gradient;
    normal.cost += terms.residual.squaredNorm();
    for (size_t g = 0; g < groups.size(); ++g) {
      if (groups[g][i]) continue;
      normal.group_information[g] += information;
      normal.group_gradient[g] += gradient;
    }
  }
  return normal;
}

double ScaledCost(const handeye::Problem& problem, const std::vector<Matrix6d>& whitening,
                  const State& state) {
  const double s = std::exp(state.log_scale);
  double cost = 0.0;
  for (size_t i = 0; i < problem.A.size(); ++i) {
    Pose scaled = problem.B[i];
    scaled.translation() *= s;
    cost += (whitening[i] * LoopResidual(problem.A[i], scaled, state.X, state.Z)).squaredNorm();
  }
  return cost;
}

State Step(const State& state, const Vector13d& delta, double length) {
  return {state.X * se3::Exp(length * delta.head<6>()),
          state.Z * se3::Exp(length * delta.segment<6>(6)), state.log_scale + length * delta(12)};
}

// Gauss–Newton with step halving from `state`; returns the optimum.
State MinimizeScaled(const handeye::Problem& problem, const std::vector<Matrix6d>& whitening,
                     State state) {
  double cost = ScaledCost(problem, whitening, state);
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Normal normal = Accumulate(problem, whitening, state, {});
    const Vector13d delta = -normal.information.ldlt().solve(normal.gradient);
    if (!delta.allFinite()) break;
    double length = 1.0;
    State next = Step(state, delta, length);
    double next_cost = ScaledCost(problem, whitening, next);
    while (!(next_cost <= cost) && length > 1e-4) {
      length /= 2;
      next = Step(state, delta, length);
      next_cost = ScaledCost(problem, whitening, next);
    }
    if (!(next_cost <= cost)) break;
    state = next;
    const bool small = (length * delta).lpNorm<Eigen::Infinity>() < 1e-12 ||
                       cost - next_cost <= 1e-14 * (1.0 + cost);
    cost = next_cost;
    if (small) break;
  }
  return state;
}

// The inverse of a symmetric information matrix through its eigen-decomposition; false when it
// is not positive definite to working precision.
bool InvertInformation(const Matrix13d& information, Matrix13d* inverse) {
  const Eigen::SelfAdjointEigenSolver<Matrix13d> eigen(information);
  const Vector13d values = eigen.eigenvalues();
  if (!(values.minCoeff() > 1e-12 * values.maxCoeff())) return false;
  *inverse =
      eigen.eigenvectors() * values.cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose();
  return true;
}

// The jackknife's variance of ε and the variance the model predicts for the same jackknife
// (model_check.h, "Leverage"), in the linearised problem at the optimum.
struct Jackknife {
  double observed = 0.0;
  double expected = 0.0;
};

Jackknife ScaleJackknife(const Normal& normal, const Matrix13d& total_inverse) {
  const size_t G = normal.group_information.size();
  std::vector<Matrix13d> without(G);
  std::vector<double> d(G);
  double mean = 0.0;
  for (size_t g = 0; g < G; ++g) {
    without[g] =
        (normal.information - normal.group_information[g]).ldlt().solve(Matrix13d::Identity());
    d[g] = -(without[g] * (normal.gradient - normal.group_gradient[g]))(12);
    mean += d[g] / static_cast<double>(G);
  }
  Jackknife jackknife;
  for (size_t g = 0; g < G; ++g) jackknife.observed += (d[g] - mean) * (d[g] - mean);
  double expected = 0.0;
  for (size_t g = 0; g < G; ++g) {
    for (size_t h = 0; h < G; ++h) {
      Matrix13d c = -normal.group_information[g] * total_inverse * normal.group_information[h];
      if (g == h) c += normal.group_information[g];
      const double term = (without[g] * c * without[h].transpose())(12, 12);
      expected -= term / static_cast<double>(G);
      if (g == h) expected += term;
    }
  }
  const double factor = (static_cast<double>(G) - 1.0) / static_cast<double>(G);
  jackknife.observed *= factor;
  jackknife.expected = factor * expected;
  return jackknife;
}

}  // namespace

bool TargetScale::Mismatch() const {
  return observable && std::abs(scale - 1.0) > kScaleMismatchSigmas * sigma;
}

handeye::Problem ScaleCameraTranslations(const handeye::Problem& problem, double scale) {
  handeye::Problem scaled = problem;
  for (Pose& B : scaled.B) B.translation() *= scale;
  return scaled;
}

TargetScale EstimateTargetScale(const handeye::Problem& problem, const Pose& X, const Pose& Z,
                                const NoiseVariances& variances,
                                const std::vector<double>& station_scale, bool estimated) {
  const size_t n = problem.A.size();
  std::vector<Matrix6d> whitening(n);
  for (size_t i = 0; i < n; ++i) {
    Matrix6d covariance =
        StationCovarianceOf(problem.setup, problem.A[i], problem.B[i], X, variances);
    if (i < station_scale.size()) covariance *= station_scale[i];
    whitening[i] = WhiteningMatrix(covariance);
  }
  TargetScale result;
  result.X = X;
  result.Z = Z;
  if (n < 3) {
    result.reason = "too few stations";
    return result;
  }
  const State optimum = MinimizeScaled(problem, whitening, {X, Z, 0.0});
  const std::vector<std::vector<bool>> groups =
      n > kModelCheckMinStations ? JackknifeGroups(n) : std::vector<std::vector<bool>>{};
  const Normal normal = Accumulate(problem, whitening, optimum, groups);
  Matrix13d inverse;
  if (!InvertInformation(normal.information, &inverse)) {
    result.reason =
        "the robot's translations do not fix the target's size (the stations only rotate, or "
        "their rotations and translations do not separate it from X's and Z's translations)";
    return result;
  }
  const double dof = 6.0 * static_cast<double>(n) - 13.0;
  result.variance_factor = estimated && dof > 0.0 ? normal.cost / dof : 1.0;
  result.scale = std::exp(optimum.log_scale);
  result.X = optimum.X;
  result.Z = optimum.Z;
  result.covariance = result.variance_factor * inverse;
  result.sensitivity = -normal.information.topLeftCorner<12, 12>().ldlt().solve(
      normal.information.topRightCorner<12, 1>());
  const double log_sigma = std::sqrt(result.covariance(12, 12));
  result.model_sigma = result.scale * log_sigma;
  if (!(log_sigma <= kMaxObservableScaleSigma)) {
    result.reason = "the robot's translations fix the target's size to no better than " +
                    std::to_string(static_cast<int>(std::round(100 * log_sigma))) +
                    " % (move the robot further between stations, about more than one axis)";
    return result;
  }
  result.observable = true;
  double ratio = 1.0;
  if (!groups.empty()) {
    const Jackknife jackknife = ScaleJackknife(normal, inverse);
    result.groups = static_cast<int>(groups.size());
    result.jackknife_sigma = result.scale * std::sqrt(jackknife.observed);
    if (jackknife.expected > 0.0) {
      // model_check.h's rule: inflate when the spread exceeds the model's beyond
      // kModelCheckFlagLevel sampling errors, shrunk by that error.
      const double observed_ratio =
          std::sqrt(jackknife.observed / (result.variance_factor * jackknife.expected));
      const double error = 0.5 * std::sqrt(2.0 / (static_cast<double>(groups.size()) - 1.0));
      if (observed_ratio > 1.0 + kModelCheckFlagLevel * error) {
        const double log_ratio = std::log(observed_ratio);
        ratio = std::exp(std::max(0.0, log_ratio - error * error / log_ratio));
      }
    }
  }
  result.sigma = result.model_sigma * ratio;
  result.covariance *= ratio * ratio;
  return result;
}

}  // namespace hecal::estimation
