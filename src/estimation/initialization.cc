#include "hecal/estimation/initialization.h"

#include <cmath>
#include <exception>

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

}  // namespace hecal::estimation
