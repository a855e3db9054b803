// Globally optimal target-free hand–eye calibration: the X = T_hand_camera that minimises the
// largest cheiral ray error max E over all bearing pairs (epipolar_problem.h), with a
// certificate. Heller, Havlena, Pajdla, "A branch-and-bound algorithm for globally optimal
// hand-eye calibration", CVPR 2012, and "Globally optimal hand-eye calibration using
// branch-and-bound", TPAMI 38(5), 2016 (Algorithm 1); the rotation-space search of Hartley &
// Kahl, "Global optimization through rotation space search", IJCV 2009.
//
// Search space: rotation vectors r in the ball |r| ≤ π (every rotation), covered by cubes, and
// translations |t| ≤ T (options.translation_bound, metres). Bisection on ε: for the level ε
// between the bounds [lower, upper], cubes are tested best first (cube_feasibility.h; lowest error
// at the parent's candidate first), in batches spread over the threads; an infeasible cube is
// pruned (and stays pruned for every smaller ε), a feasible one gives a candidate X (its centre
// rotation and the LP's translation) whose max E is evaluated, and is split into 8. Every
// candidate lowers `upper` when better; one within a quarter of the way from ε to the old upper
// bound ends the level (LP points lie on the relaxation's boundary, so demanding ≤ ε exactly
// would split cubes forever); all cubes pruned sets lower = ε. A level that lands just below the
// optimum needs cubes as small as its distance to the optimum, far more than its neighbours: a
// level may test as many cubes as the whole search before it (at least 20,000), and again as
// many while that lowers `upper`; then it is left undecided and becomes a ceiling, and the next
// levels bisect between `lower` and it (proofs there still raise `lower`). It stops when
// upper − lower ≤ max(options.epsilon, options.relative_gap · upper) (the certificate), or when
// a budget runs out (cubes, or time: options.time_budget, checked before every batch of cubes
// on options.clock, so a test can drive it); when only undecided levels are left (ceiling −
// lower ≤ half that gap) the ceiling is lifted and they are tried again with the allowance the
// search has grown to. When a budget runs out `certified` is false and the bounds are what was
// proved; Certificate::stopped_by says which end was met. While it runs, options.progress
// receives the bounds at most every options.progress_interval seconds. The incumbent comes from
// options.start (SolveGlobalRobust passes the local start, local_start.h). Results do not depend on
// the thread count (nor on the machine, unless the time budget ends the search: then on how far it
// got).
//
// The relative gap is for noisy data: there the optimum is of the order of the ray noise, and
// closing an absolute gap far below it needs cubes far smaller than the noise (their number
// grows as the cube of 1/gap near the optimum); a gap of a fraction of the optimum proves the
// same thing to the precision the noise allows, and the L2 polish takes X the rest of the way.
//
// The certificate: no X with |t| ≤ T has max E below `lower`; `X` has max E = `upper`.
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "hecal/global/epipolar_problem.h"

namespace hecal::global {

// The bounds while the search runs (SearchOptions::progress).
struct SearchProgress {
  double lower = 0.0;    // radians: proved so far
  double upper = 0.0;    // radians: max E of the incumbent
  long cubes = 0;        // tested so far
  double seconds = 0.0;  // since SolveGlobal was called (on SearchOptions::clock)
  int round = 0;         // the solve's number within SolveGlobalRobust (outlier_removal.h), from 1
};

struct SearchOptions {
  double epsilon = 1e-4;           // requested gap upper − lower (radians)
  double relative_gap = 0.0;       // or this fraction of upper, when larger
  double translation_bound = 2.0;  // T (metres): the camera lies within T of the hand origin
  double min_half_width = 1e-9;    // smallest cube (radians)
  long max_cubes = 20'000'000;     // budget of cube tests
  int threads = 0;                 // 0: every core
  std::optional<Pose> start;       // an incumbent X (e.g. from a local solve), if any
  // Stop as soon as an X with max E ≤ stop_below is found (a decision, not an optimum: used by
  // the outlier removal to ask "is everything consistent within the threshold?").
  double stop_below = -1.0;
  // Seconds from the call of SolveGlobal after which the search stops with what it has proved
  // (infinity: no limit), read on `clock` (seconds on a monotone clock; empty: the steady
  // clock). SolveGlobalRobust splits its own budget between its solves.
  double time_budget = std::numeric_limits<double>::infinity();
  std::function<double()> clock;
  std::function<void(const SearchProgress&)> progress;  // may be empty
  double progress_interval = 5.0;                       // seconds between progress calls
  int round = 0;                                        // passed on in SearchProgress::round

  // False, with the offending field named in *why (when not null), unless epsilon > 0,
  // 0 ≤ relative_gap < 1, translation_bound > 0, min_half_width > 0 (all finite),
  // time_budget > 0 (infinity allowed), progress_interval > 0 and finite,
  // max_cubes ≥ 1 and threads in 0 … kMaxThreads (core/limits.h); SolveGlobal and
  // SolveGlobalRobust throw it as an InputError (core/options_check.h).
  bool IsValid(std::string* why) const;
};

// Why a search ended: the requested gap closed (certified), an X within stop_below found, or a
// budget ran out (cubes or time; the certificate then holds the bounds proved so far).
enum class StopReason { kGapReached, kBelowThreshold, kMaxCubes, kTimeBudget };

// "gap reached", "below threshold", "max cubes", "time budget" (the result file's words).
std::string_view StopReasonName(StopReason reason);

// The search's clock when SearchOptions::clock is empty: seconds on std::chrono::steady_clock.
double SteadySeconds();

struct Certificate {
  double lower = 0.0;  // radians: no X reaches a smaller max E
  double upper = 0.0;  // radians: max E of the returned X
  long cubes = 0;      // cubes tested
  long lps = 0;        // linear programmes solved
  double seconds = 0.0;
  bool certified = false;  // upper − lower ≤ max(epsilon, relative_gap · upper)
  StopReason stopped_by = StopReason::kGapReached;
};

struct GlobalSolution {
  Pose X = Pose::Identity();  // T_hand_camera
  Certificate certificate;
};

// Precondition: at least one pair. Throws hecal::DegenerateError when no motion has a pair.
GlobalSolution SolveGlobal(const EpipolarProblem& problem, const SearchOptions& options);

}  // namespace hecal::global
