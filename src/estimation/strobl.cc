#include "hecal/estimation/strobl.h"

#include <ceres/problem.h>
#include <ceres/solver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/noise_estimation.h"
#include "hecal/estimation/se3_manifold.h"
#include "hecal/estimation/strobl_cost.h"
#include "multi_start.h"
#include "small_problem.h"

namespace hecal::estimation {
namespace {

constexpr double kRatioTolerance = 1e-6;
constexpr double kMaxRatio = 1e6;  // σ_tra / σ_rot within [1/kMaxRatio, kMaxRatio] · L
constexpr double kSigmaFloor = 1e-15;

struct Weights {
  double rotation = 1.0;     // σ_rot
  double translation = 1.0;  // σ_tra
};

// Mean squared rotation and translation errors of a solution.
Weights ErrorRms(const handeye::Problem& problem, const handeye::Solution& solution) {
  double rotation = 0.0, translation = 0.0;
  for (size_t i = 0; i < problem.A.size(); ++i) {
    const Vector9d e = StroblResidual(problem.A[i], problem.B[i], solution.X, solution.Z);
    rotation += e.head<3>().squaredNorm();
    translation += e.tail<6>().squaredNorm();
  }
  const double n = static_cast<double>(problem.A.size());
  return {std::sqrt(rotation / n), std::sqrt(translation / n)};
}

Weights Bounded(Weights w, double length_scale) {
  w.rotation = std::max(w.rotation, kSigmaFloor);
  w.translation = std::max(w.translation, kSigmaFloor);
  const double ratio = w.translation / (w.rotation * length_scale);
  if (ratio > kMaxRatio) w.rotation = w.translation / (kMaxRatio * length_scale);
  if (ratio < 1.0 / kMaxRatio) w.translation = w.rotation * length_scale / kMaxRatio;
  return w;
}

double Cost(const handeye::Problem& problem, const handeye::Solution& solution, const Weights& w) {
  double cost = 0.0;
  for (size_t i = 0; i < problem.A.size(); ++i) {
    const Vector9d e = StroblResidual(problem.A[i], problem.B[i], solution.X, solution.Z);
    cost += e.head<3>().squaredNorm() / (w.rotation * w.rotation) +
            e.tail<6>().squaredNorm() / (w.translation * w.translation);
  }
  return cost;
}

handeye::Solution Minimize(const handeye::Problem& problem, const handeye::Solution& start,
                           const Weights& w) {
  double x[kPoseAmbientSize], z[kPoseAmbientSize];
  PoseToParameters(start.X, x);
  PoseToParameters(start.Z, z);
  Se3RightManifold manifold;
  ceres::Problem ceres_problem(internal::SmallProblemOptions());
  ceres_problem.AddParameterBlock(x, kPoseAmbientSize, &manifold);
  ceres_problem.AddParameterBlock(z, kPoseAmbientSize, &manifold);
  for (size_t i = 0; i < problem.A.size(); ++i) {
    ceres_problem.AddResidualBlock(
        StroblCost::Create(problem.A[i], problem.B[i], w.rotation, w.translation), nullptr, x, z);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(internal::SmallSolverOptions(), &ceres_problem, &summary);
  return {PoseFromParameters(x), PoseFromParameters(z)};
}

}  // namespace

bool StroblOptions::IsValid(std::string* why) const {
  if (max_iterations >= 1) return true;
  return Invalid(why, "StroblOptions.max_iterations",
                 "must be at least 1, got " + std::to_string(max_iterations), "use e.g. 20");
}

StroblResult RefineStrobl(const handeye::Problem& problem,
                          const std::vector<handeye::Solution>& starts,
                          const StroblOptions& options) {
  RequireValid(options);
  if (starts.empty()) throw std::invalid_argument("RefineStrobl: no starting solution");
  if (problem.A.size() != problem.B.size()) {
    throw std::invalid_argument("RefineStrobl: one camera pose per robot pose");
  }
  if (problem.A.size() < 3) {
    throw DegenerateError("X and Z from fewer than 3 stations", "record at least 3 stations");
  }
  const double L = handeye::LengthScale(problem);
  Weights weights{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (const handeye::Solution& start : starts) {
    const Weights rms = ErrorRms(problem, start);
    weights.rotation = std::min(weights.rotation, rms.rotation);
    weights.translation = std::min(weights.translation, rms.translation);
  }
  weights = Bounded(weights, L);

  StroblResult result;
  const internal::MultiStartResult multi = internal::RunMultiStart(
      starts, L, [&](const handeye::Solution& start) { return Cost(problem, start, weights); },
      [&](const handeye::Solution& start) {
        const handeye::Solution optimum = Minimize(problem, start, weights);
        return internal::Optimum{optimum, Cost(problem, optimum, weights)};
      });
  result.starts_refined = multi.starts_refined;
  handeye::Solution best = multi.best.solution;

  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    const Weights next = Bounded(ErrorRms(problem, best), L);
    const double ratio = weights.translation / weights.rotation;
    const double next_ratio = next.translation / next.rotation;
    weights = next;
    ++result.iterations;
    if (std::abs(next_ratio - ratio) <= kRatioTolerance * ratio) break;
    best = Minimize(problem, best, weights);
  }
  result.X = best.X;
  result.Z = best.Z;
  result.sigma_rotation = weights.rotation;
  result.sigma_translation = weights.translation;
  result.cost = Cost(problem, best, weights);
  return result;
}

}  // namespace hecal::estimation
