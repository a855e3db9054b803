#include "loop_solver.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "fixed_size_kernels.h"
#include "hecal/estimation/robust_loss.h"
#include "hecal/geometry/se3.h"

namespace hecal::estimation::internal {
namespace {

constexpr int kMaxIterations = 100;
constexpr double kInitialRadius = 1e4;
constexpr double kMaxRadius = 1e16;
constexpr double kMinRadius = 1e-32;
constexpr double kMinDiagonal = 1e-6;
constexpr double kMaxDiagonal = 1e32;
constexpr double kMinRelativeDecrease = 1e-3;
constexpr double kFunctionTolerance = 1e-14;
constexpr double kGradientTolerance = 1e-16;
constexpr double kParameterTolerance = 1e-13;

double ParameterNorm(const handeye::Solution& solution) {
  return std::sqrt(2.0 + solution.X.translation().squaredNorm() +
                   solution.Z.translation().squaredNorm());
}

// With one component of X's translation given (planar.h): the normal equations restricted to the
// constraint's tangent, P H P + α (I − P) and P g with P = U Uᵀ (U = FixTangentBasis, α the mean
// of diag H), so that every step keeps the fixed coordinate to first order; ApplyFix then puts
// the candidate exactly on the constraint.
void RestrictToFix(const handeye::Solution& at, const handeye::FixedTranslation& fixed,
                   LoopNormalEquations* equations) {
  const Eigen::Matrix<double, 12, 11> U = handeye::FixTangentBasis(at, fixed);
  const Matrix12d P = U * U.transpose();
  const double alpha = std::max(equations->hessian.diagonal().mean(), kMinDiagonal);
  equations->hessian =
      P * equations->hessian * P + alpha * (Matrix12d::Identity() - P);
  equations->gradient = P * equations->gradient;
}

}  // namespace

double LoopCostValue(const handeye::Problem& problem, const std::vector<Matrix6d>& whitening,
                     const ceres::LossFunction* loss, const handeye::Solution& solution) {
  double cost = 0.0;
  for (size_t i = 0; i < whitening.size(); ++i) {
    const Vector6d r = LoopResidual(problem.A[i], problem.B[i], solution.X, solution.Z);
    cost += LossValue(loss, (whitening[i] * r).squaredNorm());
  }
  return cost;
}

LoopNormalEquations LinearizeLoopCost(const handeye::Problem& problem,
                                      const std::vector<Matrix6d>& whitening,
                                      const ceres::LossFunction* loss,
                                      const handeye::Solution& solution) {
  LoopNormalEquations equations;
  Matrix6x12d J;
  for (size_t i = 0; i < whitening.size(); ++i) {
    const Vector6d r = LoopResidual(problem.A[i], problem.B[i], solution.X, solution.Z, &J);
    const Matrix6d& W = whitening[i];
    const Vector6d whitened = W * r;
    const Matrix6x12d WJ = W.lazyProduct(J);
    const double s = whitened.squaredNorm();
    const double weight = LossWeight(loss, s);
    equations.cost += LossValue(loss, s);
    AddWeightedGram(WJ, weight, &equations.hessian);
    equations.gradient.noalias() += weight * WJ.transpose() * whitened;
  }
  return equations;
}

handeye::Solution MinimizeLoopCost(const handeye::Problem& problem,
                                   const std::vector<Matrix6d>& whitening,
                                   const ceres::LossFunction* loss,
                                   const handeye::Solution& start,
                                   const handeye::FixedTranslation* fixed) {
  handeye::Solution current = fixed ? handeye::ApplyFix(start, *fixed) : start;
  const auto linearize = [&](const handeye::Solution& at) {
    LoopNormalEquations equations = LinearizeLoopCost(problem, whitening, loss, at);
    if (fixed) RestrictToFix(at, *fixed, &equations);
    return equations;
  };
  LoopNormalEquations equations = linearize(current);
  double radius = kInitialRadius;
  double nu = 2.0;
  bool newton_decrease_due = true;  // after each linearisation
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    if (!(equations.gradient.lpNorm<Eigen::Infinity>() > kGradientTolerance)) break;
    if (newton_decrease_due) {
      // The most the model can still gain: ½ gᵀ H⁻¹ g, at its minimum.
      const double newton_decrease =
          0.5 * equations.gradient.dot(equations.hessian.ldlt().solve(equations.gradient));
      if (newton_decrease <= kFunctionTolerance * 0.5 * equations.cost) break;
      newton_decrease_due = false;
    }
    Matrix12d damped = equations.hessian;
    damped.diagonal() +=
        equations.hessian.diagonal().cwiseMax(kMinDiagonal).cwiseMin(kMaxDiagonal) / radius;
    const Vector12d step = -damped.ldlt().solve(equations.gradient);
    if (!step.allFinite()) break;
    if (step.norm() <= kParameterTolerance * (ParameterNorm(current) + kParameterTolerance)) break;
    handeye::Solution candidate{current.X * se3::Exp(step.head<6>()),
                                current.Z * se3::Exp(step.tail<6>())};
    if (fixed) candidate = handeye::ApplyFix(candidate, *fixed);
    const double candidate_cost = LoopCostValue(problem, whitening, loss, candidate);
    const double predicted =
        -(equations.gradient.dot(step) + 0.5 * step.dot(equations.hessian * step));
    const double actual = 0.5 * (equations.cost - candidate_cost);
    const double ratio = predicted > 0.0 ? actual / predicted : -1.0;
    if (std::isfinite(candidate_cost) && ratio > kMinRelativeDecrease) {
      const bool converged = actual <= kFunctionTolerance * 0.5 * equations.cost;
      current = candidate;
      if (converged) break;
      equations = linearize(current);
      newton_decrease_due = true;
      radius =
          std::min(kMaxRadius, radius / std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * ratio - 1.0, 3)));
      nu = 2.0;
    } else {
      radius /= nu;
      nu *= 2.0;
      if (radius < kMinRadius) break;
    }
  }
  return current;
}

}  // namespace hecal::estimation::internal
