// Google Benchmark: every hecal hand–eye solver, and OpenCV 4.6's peer where it has one, at
// n = 10, 20, 50 stations on IDENTICAL data: the thesis protocol (sim/thesis_protocol.h,
// eye-in-hand) with Gaussian noise 0.1 mm / 0.1° on robot and camera, 8 data sets per n, cycled
// through the iterations.
//
// Correctness is checked as well as speed (PoseLib style): before timing, each solver solves
// every data set once and the benchmark reports counters
//   rot_err_deg   RMS rotation error of X over the data sets (angle of R_true⁻¹ R_est)
//   trans_err_mm  RMS translation error of X
//   failures      data sets where it threw, returned a non-finite pose, or erred by > 10°
// A hecal solver whose error exceeds 1° or 10 mm on any data set (≈ 20× what this noise gives)
// is reported as an error (SkipWithError). OpenCV's results are reported, not judged: on this
// protocol its TSAI, HORAUD and DANIILIDIS fail, and that is part of the comparison.
//
// The protocol is `hecal bench`'s (study/bench.h): the same data sets (MakeBenchDataSets, seed
// 1), the same solvers — strobl and ml solve only (no covariance, no model check), told the true
// sigmas — the same OpenCV peer (jobs/opencv_bench_peer.h) and the same accuracy
// (MeasureAccuracy); Google Benchmark does the timing.
// hecal/ml-good-start/<n> times ml re-solved from a good start the way the model check's
// jackknife and the covariance propagation re-solve (study::GoodStartMlSolver: estimation::Resolve
// from the calibration's result with X and Z replaced by the truth); compare with hecal/ml/<n>,
// which starts from every closed-form solution after the outlier rejection.
//
//   handeye_bench [--benchmark_filter=opencv/park-martin/50] [other Google Benchmark flags]
// Names: <impl>/<method>/<stations>, impl = hecal | opencv.
#include <benchmark/benchmark.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/methods.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/study/bench.h"
#ifdef HECAL_HAVE_OPENCV_PEERS
#include "hecal/jobs/opencv_bench_peer.h"
#endif

namespace {

namespace estimation = hecal::estimation;
namespace handeye = hecal::handeye;
namespace study = hecal::study;
constexpr study::NoiseLevel kSigma = {0.1, 0.1};  // mm / deg per component
constexpr int kDataSets = 8;

const std::vector<study::BenchDataSet>& DataSets(int stations) {
  static std::vector<std::vector<study::BenchDataSet>> cache(64);
  std::vector<study::BenchDataSet>& sets = cache[stations];
  if (sets.empty()) {
    sets = study::MakeBenchDataSets(handeye::Setup::kEyeInHand, stations, kDataSets, kSigma, 1);
  }
  return sets;
}

void RunSolver(benchmark::State& state, const study::BenchSolver& solve, int stations, bool judge) {
  const std::vector<study::BenchDataSet>& sets = DataSets(stations);
  const study::BenchAccuracy accuracy = study::MeasureAccuracy(sets, solve);
  if (judge &&
      (accuracy.finite < kDataSets || accuracy.worst_rotation * hecal::kDegreesPerRadian > 1.0 ||
       accuracy.worst_translation > 0.01)) {
    state.SkipWithError("wrong result: error above 1 deg / 10 mm, or a failed solve");
    return;
  }
  size_t next = 0;
  for (auto _ : state) {
    const size_t i = next;
    next = (next + 1) % sets.size();
    try {
      hecal::Pose X = solve(i);
      benchmark::DoNotOptimize(X);
    } catch (const std::exception&) {
      benchmark::ClobberMemory();
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  state.counters["rot_err_deg"] = accuracy.rotation_error.value_or(nan) * hecal::kDegreesPerRadian;
  state.counters["trans_err_mm"] = accuracy.translation_error.value_or(nan) * 1e3;
  state.counters["failures"] = accuracy.failures;
}

void RegisterAll() {
  for (const estimation::MethodInfo& info : estimation::AllMethods()) {
    for (int n : {10, 20, 50}) {
      const std::string suffix = std::string(info.name) + "/" + std::to_string(n);
      const estimation::Method method = info.method;
      benchmark::RegisterBenchmark(("hecal/" + suffix).c_str(), [method,
                                                                 n](benchmark::State& state) {
        RunSolver(state, study::HecalSolver(method, DataSets(n), kSigma), n, /*judge=*/true);
      })->Unit(benchmark::kMicrosecond);
      if (method == estimation::Method::kMl) {
        benchmark::RegisterBenchmark(("hecal/ml-good-start/" + std::to_string(n)).c_str(),
                                     [n](benchmark::State& state) {
                                       RunSolver(state,
                                                 study::GoodStartMlSolver(DataSets(n), kSigma), n,
                                                 /*judge=*/true);
                                     })
            ->Unit(benchmark::kMicrosecond);
      }
#ifdef HECAL_HAVE_OPENCV_PEERS
      if (hecal::jobs::HasOpenCvBenchPeer(method)) {
        benchmark::RegisterBenchmark(("opencv/" + suffix).c_str(), [method,
                                                                    n](benchmark::State& state) {
          // Inputs converted once, outside the timing.
          const std::optional<study::BenchSolver> solve =
              hecal::jobs::OpenCvBenchPeer().prepare(method, DataSets(n));
          RunSolver(state, *solve, n, /*judge=*/false);
        })->Unit(benchmark::kMicrosecond);
      }
#endif
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  RegisterAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
