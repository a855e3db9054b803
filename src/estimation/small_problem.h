// Internal: Ceres settings shared by the refinements. The problems are tiny (two pose blocks,
// 12 tangent unknowns, 6–9 residuals per station) and are solved thousands of times by
// `hecal simulate`, so: dense QR, one thread, no logging, tight tolerances (noise-free data
// must converge to 1e-9 and beyond).
#pragma once

#include <ceres/problem.h>
#include <ceres/solver.h>

namespace hecal::estimation::internal {

inline ceres::Problem::Options SmallProblemOptions() {
  ceres::Problem::Options options;
  options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.enable_fast_removal = false;
  return options;
}

inline ceres::Solver::Options SmallSolverOptions() {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-13;
  return options;
}

}  // namespace hecal::estimation::internal
