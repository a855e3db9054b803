#include "hecal/global/branch_and_bound.h"

#include <glpk.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/so3.h"
#include "hecal/global/cube_feasibility.h"
#include "hecal/uncertainty/parallel_for.h"

namespace hecal::global {

bool SearchOptions::IsValid(std::string* why) const {
  if (!(epsilon > 0.0) || !std::isfinite(epsilon)) {
    return Invalid(why, "SearchOptions.epsilon", "must be above 0 and finite",
                   "give the certificate's gap in radians, e.g. 2e-4");
  }
  if (!(relative_gap >= 0.0 && relative_gap < 1.0)) {
    return Invalid(why, "SearchOptions.relative_gap", "must be at least 0 and below 1",
                   "give a fraction of the optimum, e.g. 0.1 (0: ε only)");
  }
  if (!(translation_bound > 0.0) || !std::isfinite(translation_bound)) {
    return Invalid(why, "SearchOptions.translation_bound", "must be above 0 and finite",
                   "give the largest |t| of X in metres, e.g. 2");
  }
  if (!(min_half_width > 0.0) || !std::isfinite(min_half_width)) {
    return Invalid(why, "SearchOptions.min_half_width", "must be above 0 and finite",
                   "give the smallest cube in radians, e.g. 1e-9");
  }
  if (!(time_budget > 0.0)) {
    return Invalid(why, "SearchOptions.time_budget", "must be above 0",
                   "give the search's time in seconds, e.g. 120 (infinity: no limit)");
  }
  if (!(progress_interval > 0.0) || !std::isfinite(progress_interval)) {
    return Invalid(why, "SearchOptions.progress_interval", "must be above 0 and finite",
                   "give the seconds between progress calls, e.g. 5");
  }
  if (max_cubes < 1) {
    return Invalid(why, "SearchOptions.max_cubes", "must be at least 1",
                   "give the search's budget of cube tests, e.g. 1000000");
  }
  return ThreadCountValid(threads, "SearchOptions.threads", why);
}

std::string_view StopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::kGapReached:
      return "gap reached";
    case StopReason::kBelowThreshold:
      return "below threshold";
    case StopReason::kMaxCubes:
      return "max cubes";
    case StopReason::kTimeBudget:
      return "time budget";
  }
  return "gap reached";
}

double SteadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

namespace {

struct Cube {
  Eigen::Vector3d centre;
  double half_width = 0.0;
  double infeasible_at = -1.0;  // the largest ε at which the cube was proved infeasible
  double score = 0.0;           // max E at the parent's candidate (best-first order)
  Eigen::Vector3d hint = Eigen::Vector3d::Zero();  // the parent's candidate translation
};

// Whether the cube meets the ball |r| ≤ π.
bool MeetsBall(const Cube& cube) {
  const Eigen::Vector3d nearest =
      cube.centre.cwiseAbs() - Eigen::Vector3d::Constant(cube.half_width);
  return nearest.cwiseMax(0.0).norm() <= M_PI;
}

struct Outcome {
  bool feasible = false;
  double error = std::numeric_limits<double>::infinity();
  Pose X = Pose::Identity();
  int lps = 0;
};

class Search {
 public:
  Search(const EpipolarProblem& problem, const SearchOptions& options)
      : problem_(problem),
        options_(options),
        clock_(options.clock ? options.clock : SteadySeconds),
        begin_(clock_()),
        last_progress_(begin_) {
    threads_ = options.threads > 0 ? options.threads
                                   : std::max(1, int(std::thread::hardware_concurrency()));
    leaves_.push_back({Eigen::Vector3d::Zero(), M_PI, -1.0, 0.0, Eigen::Vector3d::Zero()});
    if (options.start) Offer(*options.start, MaxRayError(problem, *options.start));
  }

  GlobalSolution Run() {
    double& lower = lower_;
    // A level just below the optimum needs cubes as small as its distance to the optimum, far
    // more than its neighbours: one left undecided after its budget becomes a ceiling, and the
    // next levels bisect below it (each proof still raises `lower`).
    double ceiling = std::numeric_limits<double>::infinity();
    while (best_error_ - lower > Gap() && best_error_ > options_.stop_below &&
           cubes_ < options_.max_cubes && !OutOfTime()) {
      const double top = std::min(best_error_, ceiling);
      if (top - lower <= 0.5 * Gap()) {
        // Only undecided levels are left: retry them (the allowance has grown with the search).
        ceiling = std::numeric_limits<double>::infinity();
        continue;
      }
      const double level = std::isfinite(top) ? 0.5 * (lower + top) : M_PI / 4;
      switch (Decide(level)) {
        case Answer::kYes:
          break;  // best_error_ ≤ level + (old upper − level) / 4
        case Answer::kNo:
          lower = level;
          break;
        case Answer::kUnknown:
          ceiling = level;
          break;
      }
    }
    GlobalSolution solution;
    solution.X = best_;
    solution.certificate.lower = std::min(lower, best_error_);
    solution.certificate.upper = best_error_;
    solution.certificate.cubes = cubes_;
    solution.certificate.lps = lps_;
    solution.certificate.certified = best_error_ - lower <= Gap();
    solution.certificate.stopped_by = solution.certificate.certified ? StopReason::kGapReached
                                      : best_error_ <= options_.stop_below
                                          ? StopReason::kBelowThreshold
                                      : out_of_time_ ? StopReason::kTimeBudget
                                                     : StopReason::kMaxCubes;
    solution.certificate.seconds = clock_() - begin_;
    return solution;
  }

 private:
  enum class Answer { kYes, kNo, kUnknown };

  // Whether the time budget has run out (once out, it stays out); hands out the bounds to
  // options_.progress when progress_interval has passed since the last time.
  bool OutOfTime() {
    if (out_of_time_) return true;
    const double now = clock_();
    if (options_.progress && now - last_progress_ >= options_.progress_interval) {
      last_progress_ = now;
      options_.progress(
          {std::min(lower_, best_error_), best_error_, cubes_, now - begin_, options_.round});
    }
    out_of_time_ = now - begin_ >= options_.time_budget;
    return out_of_time_;
  }

  // The requested gap at the current upper bound.
  double Gap() const {
    return std::isfinite(best_error_)
               ? std::max(options_.epsilon, options_.relative_gap * best_error_)
               : options_.epsilon;
  }

  void Offer(const Pose& X, double error) {
    if (error < best_error_) {
      best_error_ = error;
      best_ = X;
    }
  }

  Outcome Evaluate(const Cube& cube, double level) const {
    Outcome outcome;
    CubeQuery query{cube.centre, cube.half_width, level, options_.translation_bound};
    const auto t = TestCube(problem_, query, cube.hint, &outcome.lps);
    if (!t) return outcome;
    outcome.feasible = true;
    const Eigen::Matrix3d R = so3::Exp(cube.centre);
    outcome.X = MakePose(R, *t);
    outcome.error = MaxRayError(problem_, outcome.X);
    if (outcome.error > level && cube.half_width > 0.0) {
      // The pyramid is looser than the cone near the caps: the centre rotation alone at a
      // tighter level often gives a candidate that the wider test did not.
      query.half_width = 0.0;
      query.epsilon = 0.9 * level;
      if (const auto t_centre = TestCube(problem_, query, *t, &outcome.lps)) {
        const Pose X = MakePose(R, *t_centre);
        const double error = MaxRayError(problem_, X);
        if (error < outcome.error) {
          outcome.error = error;
          outcome.X = X;
        }
      }
    }
    return outcome;
  }

  // Is there an X with max E ≤ level? No (proved), unknown (budget), or yes: found an X whose
  // error is at most `enough` (a quarter of the way from the level to the old upper bound; the
  // LP's points lie on the boundary of the relaxation, so asking for ≤ level exactly would
  // split cubes forever for candidates a rounding error above it).
  Answer Decide(double level) {
    const double enough = std::isfinite(best_error_) ? level + 0.25 * (best_error_ - level) : level;
    std::vector<Cube> work, kept;
    for (Cube& cube : leaves_) (cube.infeasible_at >= level ? kept : work).push_back(cube);
    bool found = false, unresolved = false;
    constexpr int batch_size = 128;  // independent of the threads: the same search on any count
    // A heap with the lowest score on top: best first without re-sorting the whole front.
    const auto later = [](const Cube& a, const Cube& b) { return a.score > b.score; };
    std::make_heap(work.begin(), work.end(), later);
    // A level may test as many cubes as the whole search before it (at least kMinLevelCubes),
    // and again as many while that finds better candidates; then it is left undecided (Run).
    constexpr long kMinLevelCubes = 20'000;
    const long allowance = std::max(kMinLevelCubes, cubes_);
    long budget = std::min(options_.max_cubes, cubes_ + allowance);
    double error_at_budget = best_error_;
    while (!work.empty() && !found) {
      if (cubes_ >= budget && best_error_ < error_at_budget && budget < options_.max_cubes) {
        budget = std::min(options_.max_cubes, budget + allowance);
        error_at_budget = best_error_;
      }
      if (cubes_ >= budget || OutOfTime()) {
        unresolved = true;
        break;
      }
      const int count = std::min<int>(batch_size, int(work.size()));
      std::vector<Cube> batch;
      batch.reserve(count);
      for (int i = 0; i < count; ++i) {
        std::pop_heap(work.begin(), work.end(), later);
        batch.push_back(std::move(work.back()));
        work.pop_back();
      }
      std::vector<Outcome> outcomes(batch.size());
      const int chunks = std::min<int>(count, 4 * threads_);
      uncertainty::ParallelFor(chunks, threads_, [&](int chunk) {
        for (int i = chunk; i < count; i += chunks) outcomes[i] = Evaluate(batch[i], level);
        glp_free_env();  // GLPK keeps one environment per thread
      });
      for (int i = 0; i < count; ++i) {
        Cube& cube = batch[i];
        const Outcome& outcome = outcomes[i];
        ++cubes_;
        lps_ += outcome.lps;
        if (!outcome.feasible) {
          cube.infeasible_at = level;
          kept.push_back(cube);
          continue;
        }
        Offer(outcome.X, outcome.error);
        if (outcome.error <= enough) found = true;
        if (cube.half_width / 2 < options_.min_half_width) {
          unresolved = true;
          kept.push_back(cube);
          continue;
        }
        const double half = cube.half_width / 2;
        for (int k = 0; k < 8; ++k) {
          Cube child = cube;
          child.half_width = half;
          child.score = outcome.error;
          child.hint = outcome.X.translation();
          for (int axis = 0; axis < 3; ++axis) {
            child.centre[axis] += ((k >> axis) & 1) ? half : -half;
          }
          if (MeetsBall(child)) {
            work.push_back(child);
            std::push_heap(work.begin(), work.end(), later);
          }
        }
      }
    }
    kept.insert(kept.end(), work.begin(), work.end());
    leaves_ = std::move(kept);
    if (found || best_error_ <= enough) return Answer::kYes;
    return unresolved ? Answer::kUnknown : Answer::kNo;
  }

  const EpipolarProblem& problem_;
  const SearchOptions& options_;
  std::function<double()> clock_;
  double begin_ = 0.0;  // clock_() at the start
  double last_progress_ = 0.0;
  bool out_of_time_ = false;
  double lower_ = 0.0;  // proved so far
  int threads_ = 1;
  std::vector<Cube> leaves_;
  Pose best_ = Pose::Identity();
  double best_error_ = std::numeric_limits<double>::infinity();
  long cubes_ = 0;
  long lps_ = 0;
};

}  // namespace

GlobalSolution SolveGlobal(const EpipolarProblem& problem, const SearchOptions& options) {
  RequireValid(options);
  if (PairCount(problem) == 0) {
    throw DegenerateError("the hand–eye transform from no bearing pairs",
                          "give point matches between the images of at least two motions");
  }
  return Search(problem, options).Run();
}

}  // namespace hecal::global
