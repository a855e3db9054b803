#include "hecal/handeye/solver_support.h"

#include <cmath>
#include <string>

#include "hecal/core/error.h"

namespace hecal::handeye {
namespace {

double RootMeanSquare(double sum_of_squares, size_t count) {
  const double rms = count > 0 ? std::sqrt(sum_of_squares / static_cast<double>(count)) : 0.0;
  return rms > 0.0 ? rms : 1.0;
}

}  // namespace

void RequireMotions(const std::vector<Motion>& motions, size_t minimum) {
  if (motions.size() < minimum) {
    throw DegenerateError("the hand-eye pose from " + std::to_string(motions.size()) +
                              " motion(s) (at least " + std::to_string(minimum) + " needed)",
                          "use at least 3 stations with different rotation axes");
  }
}

void RequireStations(const Problem& problem, size_t minimum) {
  if (problem.A.size() < minimum || problem.A.size() != problem.B.size()) {
    throw DegenerateError("X and Z from " + std::to_string(problem.A.size()) +
                              " station(s) (at least " + std::to_string(minimum) + " needed)",
                          "use at least 3 stations with different rotation axes");
  }
}

double TranslationScale(const std::vector<Motion>& motions) {
  double sum = 0.0;
  for (const Motion& motion : motions) {
    sum += motion.A.translation().squaredNorm() + motion.B.translation().squaredNorm();
  }
  return RootMeanSquare(sum, 2 * motions.size());
}

double TranslationScale(const Problem& problem) {
  double sum = 0.0;
  for (const Pose& A : problem.A) sum += A.translation().squaredNorm();
  for (const Pose& B : problem.B) sum += B.translation().squaredNorm();
  return RootMeanSquare(sum, problem.A.size() + problem.B.size());
}

}  // namespace hecal::handeye
