#include "hecal/estimation/station_selection.h"

#include <algorithm>

#include "hecal/estimation/initialization.h"
#include "hecal/estimation/ml.h"
#include "hecal/handeye/observability.h"

namespace hecal::estimation {
namespace {

constexpr int kMaxRounds = 5;

int CountUnused(const std::vector<bool>& used) {
  return static_cast<int>(std::count(used.begin(), used.end(), false));
}

}  // namespace

std::vector<int> StationSelection::Rejected() const {
  std::vector<int> rejected;
  for (size_t i = 0; i < used.size(); ++i)
    if (!used[i]) rejected.push_back(static_cast<int>(i));
  return rejected;
}

StationSelection AllStations(size_t n) {
  StationSelection selection;
  selection.used.assign(n, true);
  return selection;
}

StationSelection SelectStations(const handeye::Problem& problem,
                                const StationSelectionOptions& options) {
  const size_t n = problem.A.size();
  if (n < 3) handeye::CheckObservability(problem);  // throws: too few stations
  StationSelection selection = AllStations(n);
  const int max_rejected = static_cast<int>((n - 3) / 2);
  if (max_rejected == 0) return selection;

  selection.consensus = handeye::FindStationConsensus(problem, options.consensus);
  std::vector<bool> candidate = selection.consensus.inlier;
  // A consensus that leaves out more than may be rejected is no basis: test from all stations.
  if (CountUnused(candidate) > max_rejected) candidate.assign(n, true);

  MlOptions ml_options;
  ml_options.robot_sigma = options.robot_sigma;
  ml_options.camera_sigma = options.camera_sigma;
  for (int round = 0; round < kMaxRounds; ++round) {
    const handeye::Problem set = handeye::SubProblem(problem, candidate);
    handeye::CheckObservability(set);
    const MlResult fit = RefineMl(set, StartingSolutions(set), ml_options);
    selection.tests =
        TestStations(LinearizeStations(problem, fit.X, fit.Z), candidate, fit.noise.variances);
    selection.used = candidate;
    selection.rounds = round + 1;
    std::vector<bool> next(n);
    for (size_t i = 0; i < n; ++i) next[i] = !selection.tests[i].outlier;
    selection.flagged = CountUnused(next);
    if (selection.flagged > max_rejected) {
      selection.too_many = true;
      selection.used.assign(n, true);
      return selection;
    }
    if (next == candidate) break;
    candidate = next;
  }
  return selection;
}

}  // namespace hecal::estimation
