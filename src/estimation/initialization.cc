#include "hecal/estimation/initialization.h"

#include <cmath>
#include <exception>

#include "hecal/core/error.h"

namespace hecal::estimation {
namespace {

bool IsFinite(const Pose& T) {
  return T.matrix().allFinite();
}

}  // namespace

std::vector<InitialSolution> InitialSolutions(const handeye::Problem& problem) {
  std::vector<InitialSolution> initial;
  for (const handeye::MethodInfo& info : handeye::AllMethods()) {
    if (!info.closed_form) continue;
    try {
      handeye::Solution solution = handeye::SolveClosedForm(info.method, problem);
      if (IsFinite(solution.X) && IsFinite(solution.Z)) {
        initial.push_back({info.method, solution});
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

std::vector<handeye::Solution> StartingSolutions(const handeye::Problem& problem) {
  std::vector<handeye::Solution> starts = Solutions(InitialSolutions(problem));
  if (starts.empty()) {
    throw DegenerateError("X and Z (no closed-form solver found a starting point)",
                          "check the pose conventions (try inverting the robot or camera poses) "
                          "and use stations with large, varied rotations");
  }
  return starts;
}

}  // namespace hecal::estimation
