// Removing wrong matches before and inside the global search (docs/global.md). The L∞ optimum
// is ruined by a single wrong match, so:
//  1. Per motion, a robust epipolar pre-filter: RANSAC over the essential matrix E = [t_A]× R_A
//     (linear eight-point estimate on bearings, vᵀ E u = 0; Hartley & Zisserman, "Multiple View
//     Geometry", 2nd ed., §11.2), scoring a pair by its angular Sampson error
//     |vᵀ E u| / sqrt(|P_v E u|² + |P_u Eᵀ v|²), P_x = I − x xᵀ (radians of ray);
//     pairs above options.threshold for the best model are removed. It uses no robot data.
//  Between 1 and 2, the local start (local_start.h) on the kept pairs: the search's incumbent,
//     and the data's own error level s = median(E)/0.6745 of the cheiral ray errors there (the
//     scale of |N(0, s²)|; robust to the few wrong matches left). The threshold of step 2 is
//     max(options.threshold, error_level_multiple · s): the pixel-derived threshold alone
//     removes correct matches when other errors dominate — the robot's (on real arms 0.03° and
//     0.25 mm over a few-cm baseline exceed the corners' ray noise several times) or an
//     underestimated pixel σ. A correct match beyond 4 s has probability 6e-5 under Gaussian
//     errors.
//  2. L∞ outlier removal (Sim & Hartley, "Removing outliers using the L∞ norm", CVPR 2006, as
//     used by Heller et al., TPAMI 2016 §5): solve globally; while the certified optimum exceeds
//     the threshold, remove the support set — the pairs whose error equals the optimum (one of
//     them at least is an outlier) — and solve again, warm-started at the previous X. A round
//     stops at the first X within the threshold (then every pair left is consistent with it) or
//     when the gap is a quarter of the threshold; a last solve closes the requested gap.
//     SearchOptions::time_budget is for all the solves together: each round may take half of
//     the time left, the last solve the rest; with none left the rounds stop and the last
//     solve is skipped (the bounds of the last round stand, stopped by the time budget).
// Pairs are named by (motion index, BearingPair::id). Deterministic for a given seed.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "hecal/global/branch_and_bound.h"
#include "hecal/global/epipolar_problem.h"

namespace hecal::global {

struct OutlierOptions {
  double threshold = 3e-3;  // radians of ray: the largest error an inlier may have (at least)
  // The L∞ rounds use max(threshold, error_level_multiple · s), s the data's own error scale
  // at the local start (see SolveGlobalRobust).
  double error_level_multiple = 4.0;
  int ransac_iterations = 500;
  int max_rounds = 20;  // L∞ removal rounds
  std::uint64_t seed = 1;

  // False, with the offending field named in *why (when not null), unless threshold > 0 and
  // error_level_multiple ≥ 0 (both finite), ransac_iterations ≥ 1 and max_rounds ≥ 1.
  bool IsValid(std::string* why) const;
};

struct RemovedPair {
  int motion = 0;
  int id = 0;
  bool by_prefilter = true;  // else by the L∞ support-set removal
};

struct RobustGlobalSolution {
  GlobalSolution solution;  // on the inliers (the certificate of the last solve)
  EpipolarProblem inliers;  // the problem without the removed pairs
  std::vector<RemovedPair> removed;
  int rounds = 0;            // global solves
  double error_scale = 0.0;  // s (radians; 0 without a local start)
  double threshold = 0.0;    // the L∞ rounds' threshold (radians)
  double seconds = 0.0;      // of every solve, on SearchOptions::clock
};

// The problem without the pairs the pre-filter rejects (step 1); appends them to `removed`.
EpipolarProblem PrefilterPairs(const EpipolarProblem& problem, const OutlierOptions& options,
                               std::vector<RemovedPair>* removed);

// Steps 1 and 2.
RobustGlobalSolution SolveGlobalRobust(const EpipolarProblem& problem, const SearchOptions& search,
                                       const OutlierOptions& options);

}  // namespace hecal::global
