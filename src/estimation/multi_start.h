// Internal: the multi-start loop shared by the refinements (ml, strobl).
//
// Starts are refined in order of their initial objective value; a start within kBasinRotation
// (2°) and kBasinTranslation·L of an optimum already found — for both X and Z — is skipped (it
// lies in that optimum's basin: wrong minima of these problems are tens of degrees away), so
// typical data cost one or two solves. The optimum with the lowest objective is kept.
#pragma once

#include <functional>
#include <vector>

#include "hecal/handeye/problem.h"

namespace hecal::estimation::internal {

inline constexpr double kBasinRotation = 0.035;     // rad (2°)
inline constexpr double kBasinTranslation = 0.035;  // × length scale
inline constexpr double kSameRotation = 1e-4;       // rad: two optima closer than this are one
inline constexpr double kSameTranslation = 1e-4;    // × length scale

struct Optimum {
  handeye::Solution solution;
  double value = 0.0;  // objective (lower is better)
};

struct MultiStartResult {
  Optimum best;
  int starts_refined = 0;
  int distinct_minima = 0;
};

bool NearSolution(const handeye::Solution& a, const handeye::Solution& b, double rotation,
                  double translation);

// `evaluate(start)` gives a start's initial objective; `refine(start)` runs the local solver.
// Requires a non-empty `starts`; optima with a non-finite objective are dropped, and
// DegenerateError is thrown if none is left.
MultiStartResult RunMultiStart(const std::vector<handeye::Solution>& starts, double length_scale,
                               const std::function<double(const handeye::Solution&)>& evaluate,
                               const std::function<Optimum(const handeye::Solution&)>& refine);

}  // namespace hecal::estimation::internal
