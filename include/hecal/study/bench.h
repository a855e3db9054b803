// The benchmark protocol of `hecal bench` and bench/handeye_bench.cc (docs/bench.md): every hecal
// solver, and a peer implementation's where it has one (OpenCV 4.6, jobs/opencv_bench_peer.h,
// supplied by the caller so this layer stays free of OpenCV), timed and scored on IDENTICAL
// generated data.
//
// Data: per station count, `datasets` data sets of the thesis protocol (sim/thesis_protocol.h)
// with Gaussian noise of the given level on both devices; data set d of n stations draws from a
// std::mt19937_64 seeded with TrialSeed(seed, setup, n, d) (study.h), so every solver, and the
// simulate study, sees the same data for the same seed.
// Solvers (BenchSolver): the closed forms through handeye::SolveClosedForm (observability check,
// motions, X and Z); strobl and ml through estimation::Calibrate told the true sigmas (estimated
// when the level is 0), starting from every closed-form solution, without covariance and model
// check (the solve only, like the closed forms and the peer); and ml from a good start
// (GoodStartMlSolver) through estimation::Resolve — the re-solve the model check's jackknife and
// the covariance propagation run — from the true X and Z with the sigmas a calibration of the
// set uses. The good start is the calibration's own result with X and Z replaced by the truth
// (off the data's optimum by about the estimate's own error, as a calibration's estimate is for
// its jackknife or resampled data sets), so the re-solve holds the same noise model the
// calibration found, the situation it is timed for; a start built from the true sigmas alone
// (as handeye_bench once did) would not exist when the noise is estimated.
// Accuracy (MeasureAccuracy): RMS over the data sets of the error of X against the truth (angle
// of R_true⁻¹ R_est; translation distance in metres) over the solves that returned a finite pose;
// failures: data sets where the solver threw, returned a non-finite pose, or erred by more than
// 10°.
// Timing (RunBench): after the accuracy pass, whole passes over the data sets until `min_time`
// seconds of process CPU time have elapsed (CPU time, not wall time, so other programs sharing
// the machine do not inflate it); us_per_solve = CPU time / solves. bench/handeye_bench.cc times
// the same solvers with Google Benchmark instead.
// Bounds (BenchOptions::IsValid): stations 3 … 100000, data sets 1 … 10000 with stations ×
// data sets ≤ 10^6 poses, min_time 0 … 3600 s, noise level 0 … 1000 mm and 0 … 180 deg; a bad
// value names the field ("BenchOptions.datasets", core/options_check.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/methods.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "hecal/sim/thesis_protocol.h"
#include "hecal/study/study.h"
#include "hecal/study/study.h"

namespace hecal::study {

struct BenchOptions {
  static constexpr int kMaxStations = 100000;
  static constexpr int kMaxDatasets = 10000;
  static constexpr std::int64_t kMaxPoses = 1000000;  // stations × data sets
  static constexpr double kMaxMinTime = 3600.0;       // seconds

  std::vector<int> stations = {10, 20, 50};
  std::vector<estimation::Method> methods = EveryMethod();
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  int datasets = 10;              // per station count
  NoiseLevel sigma = {0.1, 0.1};  // on robot and camera
  double min_time = 0.2;          // timing budget per row, seconds of process CPU time
  std::uint64_t seed = 1;

  // True when every field is in its range (above); else false with "BenchOptions.<field>:
  // problem (fix: …)" in `*why`.
  bool IsValid(std::string* why) const;
};

struct BenchDataSet {
  sim::SimulatedData data;
  handeye::Problem problem;  // data.MeasuredProblem()
};

// The data sets of one station count (above).
std::vector<BenchDataSet> MakeBenchDataSets(handeye::Setup setup, int stations, int datasets,
                                            const NoiseLevel& sigma, std::uint64_t seed);

// Solves data set `index` of the sets it was made for and returns X.
using BenchSolver = std::function<Pose(std::size_t index)>;

// hecal's solver of `method` on `sets` (closed form, or strobl / ml from every closed-form
// start); `sets` must outlive it.
BenchSolver HecalSolver(estimation::Method method, const std::vector<BenchDataSet>& sets,
                        const NoiseLevel& sigma);

// ml from a good start (above); calibrates each set once here, outside any timing.
BenchSolver GoodStartMlSolver(const std::vector<BenchDataSet>& sets, const NoiseLevel& sigma);

struct BenchAccuracy {
  std::optional<double> rotation_error;     // radians, RMS over finite solves; nullopt: none
  std::optional<double> translation_error;  // metres
  double worst_rotation = 0.0;              // radians, over finite solves
  double worst_translation = 0.0;           // metres
  int finite = 0;                           // solves that returned a finite pose
  int failures = 0;                         // threw, non-finite, or more than 10°
};

// Solves every set once.
BenchAccuracy MeasureAccuracy(const std::vector<BenchDataSet>& sets, const BenchSolver& solve);

// A peer implementation: its name ("opencv") and, per method, its solver on `sets` (nullopt when
// it has no such method); input conversion belongs in `prepare`, outside the timing.
struct BenchPeer {
  std::string name;
  std::function<std::optional<BenchSolver>(estimation::Method, const std::vector<BenchDataSet>&)>
      prepare;
};

// How strobl and ml start: not applicable (closed forms, peers), from every closed-form
// solution, or from a good start.
enum class BenchStart { kNotApplicable, kClosedForm, kGood };

struct BenchRow {
  std::string impl;  // "hecal" or the peer's name
  estimation::Method method = estimation::Method::kMl;
  BenchStart start = BenchStart::kNotApplicable;
  int stations = 0;
  double us_per_solve = 0.0;
  BenchAccuracy accuracy;
  int datasets = 0;
};

struct BenchResult {
  BenchOptions options;
  // Per station count, per method: hecal's row, for ml its good-start row, then the peer's.
  std::vector<BenchRow> rows;
};

// Runs the benchmark; throws hecal::InputError when !options.IsValid.
BenchResult RunBench(const BenchOptions& options, const std::optional<BenchPeer>& peer = {});

}  // namespace hecal::study
