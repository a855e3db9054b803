#include "hecal/global/outlier_removal.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "hecal/core/options_check.h"
#include "hecal/global/essential_matrix.h"
#include "hecal/global/local_start.h"

namespace hecal::global {

bool OutlierOptions::IsValid(std::string* why) const {
  if (!(threshold > 0.0) || !std::isfinite(threshold)) {
    return Invalid(why, "OutlierOptions.threshold", "must be above 0 and finite",
                   "give the largest ray error of an inlier in radians, e.g. 3e-3");
  }
  if (!(error_level_multiple >= 0.0) || !std::isfinite(error_level_multiple)) {
    return Invalid(why, "OutlierOptions.error_level_multiple", "must be at least 0 and finite",
                   "give a multiple of the data's error scale, e.g. 4");
  }
  if (ransac_iterations < 1) {
    return Invalid(why, "OutlierOptions.ransac_iterations", "must be at least 1", "e.g. 500");
  }
  if (max_rounds < 1) {
    return Invalid(why, "OutlierOptions.max_rounds", "must be at least 1", "e.g. 20");
  }
  return true;
}

EpipolarProblem PrefilterPairs(const EpipolarProblem& problem, const OutlierOptions& options,
                               std::vector<RemovedPair>* removed) {
  EpipolarProblem kept = problem;
  std::mt19937_64 rng(options.seed);
  for (std::size_t m = 0; m < problem.motions.size(); ++m) {
    const std::vector<BearingPair>& pairs = problem.motions[m].pairs;
    const int n = int(pairs.size());
    if (n < 9) continue;  // too few to tell: the L∞ stage decides
    std::vector<int> best;
    std::vector<int> indices(n);
    for (int i = 0; i < n; ++i) indices[i] = i;
    for (int iteration = 0; iteration < options.ransac_iterations; ++iteration) {
      std::shuffle(indices.begin(), indices.end(), rng);
      const Eigen::Matrix3d E = EightPoint(pairs, {indices.begin(), indices.begin() + 8});
      std::vector<int> inliers;
      for (int i = 0; i < n; ++i) {
        if (SampsonError(E, pairs[i]) <= options.threshold) inliers.push_back(i);
      }
      if (inliers.size() > best.size()) best = inliers;
    }
    // Refit on the consensus set and re-score once.
    if (best.size() >= 8) {
      const Eigen::Matrix3d E = EightPoint(pairs, best);
      best.clear();
      for (int i = 0; i < n; ++i) {
        if (SampsonError(E, pairs[i]) <= options.threshold) best.push_back(i);
      }
    }
    std::vector<char> keep(n, 0);
    for (int i : best) keep[i] = 1;
    std::vector<BearingPair>& out = kept.motions[m].pairs;
    out.clear();
    for (int i = 0; i < n; ++i) {
      if (keep[i]) {
        out.push_back(pairs[i]);
      } else if (removed) {
        removed->push_back({int(m), pairs[i].id, true});
      }
    }
  }
  return kept;
}

RobustGlobalSolution SolveGlobalRobust(const EpipolarProblem& problem, const SearchOptions& search,
                                       const OutlierOptions& options) {
  RequireValid(search);
  RequireValid(options);
  // The time budget is for every solve together: each L∞ round may take half of what is left,
  // the last solve all of it (a round that runs out leaves the rest to the next).
  const std::function<double()> clock = search.clock ? search.clock : SteadySeconds;
  const double begin = clock();
  const auto remaining = [&] { return search.time_budget - (clock() - begin); };
  RobustGlobalSolution result;
  result.inliers = PrefilterPairs(problem, options, &result.removed);
  // The rounds only need to tell whether the optimum exceeds the threshold: they stop at an X
  // within it, or close the gap to a quarter of it; the last solve closes the requested gap.
  SearchOptions round_options = search;
  result.threshold = options.threshold;
  if (const auto start = LocalStart(result.inliers, search.translation_bound)) {
    std::vector<double> all;
    for (const std::vector<double>& motion : RayErrors(result.inliers, *start)) {
      all.insert(all.end(), motion.begin(), motion.end());
    }
    std::nth_element(all.begin(), all.begin() + all.size() / 2, all.end());
    result.error_scale = all[all.size() / 2] / 0.6745;
    result.threshold =
        std::max(options.threshold, options.error_level_multiple * result.error_scale);
    if (!search.start ||
        MaxRayError(result.inliers, *start) < MaxRayError(result.inliers, *search.start)) {
      round_options.start = start;
    }
  }
  round_options.epsilon = std::max(search.epsilon, 0.25 * result.threshold);
  round_options.stop_below = result.threshold;
  while (true) {
    round_options.time_budget = std::max(0.5 * remaining(), 1e-9);
    round_options.round = result.rounds + 1;
    result.solution = SolveGlobal(result.inliers, round_options);
    ++result.rounds;
    const double optimum = result.solution.certificate.upper;
    if (optimum <= result.threshold || result.solution.certificate.lower <= result.threshold ||
        result.rounds >= options.max_rounds) {
      break;
    }
    if (!(remaining() > 0.0)) {
      result.solution.certificate.stopped_by = StopReason::kTimeBudget;
      break;
    }
    // The support set: the pairs at the optimum's error.
    const auto errors = RayErrors(result.inliers, result.solution.X);
    const double level = optimum - std::max(search.epsilon, 1e-9 * optimum);
    for (std::size_t m = 0; m < errors.size(); ++m) {
      std::vector<BearingPair>& pairs = result.inliers.motions[m].pairs;
      std::vector<BearingPair> kept;
      for (std::size_t j = 0; j < pairs.size(); ++j) {
        if (errors[m][j] >= level) {
          result.removed.push_back({int(m), pairs[j].id, false});
        } else {
          kept.push_back(pairs[j]);
        }
      }
      pairs = std::move(kept);
    }
    round_options.start = result.solution.X;
  }
  Certificate& last = result.solution.certificate;
  if (last.upper - last.lower > std::max(search.epsilon, search.relative_gap * last.upper)) {
    SearchOptions final_options = search;
    final_options.start = result.solution.X;
    final_options.time_budget = remaining();
    final_options.round = result.rounds + 1;
    if (final_options.time_budget > 0.0) {
      // The last round solved the same pairs: its lower bound holds for this solve too.
      const double proved = last.lower;
      result.solution = SolveGlobal(result.inliers, final_options);
      ++result.rounds;
      Certificate& c = result.solution.certificate;
      c.lower = std::min(c.upper, std::max(c.lower, proved));
    } else {
      last.stopped_by = StopReason::kTimeBudget;  // the last round's bounds stand
    }
  }
  result.seconds = clock() - begin;
  return result;
}

}  // namespace hecal::global
