// Starting points for the iterative refinements (ml, strobl): every closed-form solver of
// handeye/closed_form.h run on the data (ml begins from Shah's alone and adds the others on
// demand, below). Initialisation must never be the weak point (at n = 5, σ =
// 1 mm / 1° a single Park–Martin start lands in a wrong local minimum in ~10% of trials), so the
// refinements start from all of them and keep the lowest final cost. A solver that throws (e.g.
// Daniilidis rejecting every motion pair) is skipped; degenerate data are rejected before
// (CheckObservability) by the caller. Above kMaxStartStations stations the closed forms run on
// kMaxStartStations evenly spaced ones (station ⌊k·n/kMaxStartStations⌋, k = 0, 1, …): a start only
// has to lie in the right basin (wrong minima are tens of degrees away: multi_start.h), which 500
// stations give to ~0.1° at σ = 1 mm / 1°, and the refinement then uses every station. Measured at
// n = 10⁵: the eight motion-based closed forms take 1.7–2.1 s each on every station, all ten 0.6 s
// on 500.
#pragma once

#include <cstddef>
#include <vector>

#include "hecal/handeye/closed_form.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation {

inline constexpr size_t kMaxStartStations = 500;

struct InitialSolution {
  handeye::ClosedForm form;
  handeye::Solution solution;
};

// The closed-form solutions that succeeded (on at most kMaxStartStations stations, above), in
// handeye::ClosedForms() order; empty if none did.
std::vector<InitialSolution> InitialSolutions(const handeye::Problem& problem);

// Just the solutions.
std::vector<handeye::Solution> Solutions(const std::vector<InitialSolution>& initial);

// The solutions of InitialSolutions; throws hecal::DegenerateError when no solver succeeds.
// The starts of strobl, and of ml when its first start may have found a wrong minimum.
std::vector<handeye::Solution> ClosedFormStarts(const handeye::Problem& problem);

// ml's first start (ml.h, "Starts on demand"): Shah's closed form alone (shah.h: O(n), 10 µs at
// n = 50, where the ten closed forms take 2.4 ms), on the stations above; ClosedFormStarts when
// Shah fails. RefineMl adds the other closed forms when the optimum from it may be wrong.
std::vector<handeye::Solution> StartingSolutions(const handeye::Problem& problem);

}  // namespace hecal::estimation
