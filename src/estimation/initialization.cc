#include "hecal/estimation/initialization.h"

#include <cmath>
#include <exception>

#include "hecal/core/error.h"
#include "hecal/handeye/shah.h"
#include "hecal/handeye/station_consensus.h"

namespace hecal::estimation {
namespace {

bool IsFinite(const Pose& T) {
  return T.matrix().allFinite();
}

// Every station up to kMaxStartStations, else that many evenly spaced ones.
handeye::Problem StartStations(const handeye::Problem& problem) {
  const size_t n = problem.A.size();
  if (n <= kMaxStartStations) return problem;
  std::vector<bool> used(n, false);
  for (size_t k = 0; k < kMaxStartStations; ++k) used[k * n / kMaxStartStations] = true;
  return handeye::SubProblem(problem, used);
}

}  // namespace

std::vector<InitialSolution> InitialSolutions(const handeye::Problem& problem) {
  const handeye::Problem stations = StartStations(problem);
  std::vector<InitialSolution> initial;
  for (const handeye::ClosedFormInfo& info : handeye::ClosedForms()) {
    try {
      handeye::Solution solution = handeye::SolveClosedForm(info.form, stations);
      if (IsFinite(solution.X) && IsFinite(solution.Z)) {
        initial.push_back({info.form, solution});
      }
    } catch (const std::exception&) {
      // A solver that cannot handle these data is simply not a starting point.
    }
  }
  return initial;
}

std::vector<handeye::Solution> Solutions(const std::vector<InitialSolution>& initial) {
  std::vector<handeye::Solution> solutions;
  solutions.reserve(initial.size());
  for (const InitialSolution& start : initial) solutions.push_back(start.solution);
  return solutions;
}

std::vector<handeye::Solution> ClosedFormStarts(const handeye::Problem& problem) {
  std::vector<handeye::Solution> starts = Solutions(InitialSolutions(problem));
  if (starts.empty()) {
    throw DegenerateError("X and Z (no closed-form solver found a starting point)",
                          "check the pose conventions (try inverting the robot or camera poses) "
                          "and use stations with large, varied rotations");
  }
  return starts;
}

std::vector<handeye::Solution> StartingSolutions(const handeye::Problem& problem) {
  try {
    const handeye::Solution shah = handeye::SolveShah(StartStations(problem));
    if (IsFinite(shah.X) && IsFinite(shah.Z)) return {shah};
  } catch (const std::exception&) {
    // Shah cannot handle these data: every closed form below.
  }
  return ClosedFormStarts(problem);
}

}  // namespace hecal::estimation
