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
// hecal/ml-good-start/<n> times ml re-solved from a good start the way the model check's
// jackknife and the covariance propagation re-solve (estimation::Resolve, ml.h
// RefineMlFromGoodStart): from the true X and Z (off the data's optimum by about the estimate's
// own error) with the true sigmas; compare with hecal/ml/<n>, which starts from every closed-form
// solution after the outlier rejection.
//
//   handeye_bench [--benchmark_filter=opencv/park-martin/50] [other Google Benchmark flags]
// Names: <impl>/<method>/<stations>, impl = hecal | opencv.
#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/calibration_covariance.h"
#include "hecal/handeye/methods.h"
#include "hecal/sim/thesis_protocol.h"
#include "hecal/study/study.h"
#ifdef HECAL_HAVE_OPENCV_PEERS
#include "hecal/peers/opencv_handeye.h"
#endif

namespace {

using hecal::Pose;
namespace handeye = hecal::handeye;

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kSigmaRotation = 0.1 / kDeg;  // 0.1°
constexpr double kSigmaTranslation = 1e-4;     // 0.1 mm
constexpr int kDataSets = 8;

struct DataSet {
  hecal::sim::SimulatedData data;
  handeye::Problem problem;
#ifdef HECAL_HAVE_OPENCV_PEERS
  hecal::peers::OpenCvInput opencv;
#endif
};

const std::vector<DataSet>& DataSets(int stations) {
  static std::vector<std::vector<DataSet>> cache(64);
  std::vector<DataSet>& sets = cache[stations];
  if (sets.empty()) {
    const hecal::sim::NoiseModel noise{hecal::sim::NoiseModel::Kind::kGaussian, kSigmaRotation,
                                       kSigmaTranslation};
    for (int d = 0; d < kDataSets; ++d) {
      std::mt19937_64 rng(hecal::study::TrialSeed(1, handeye::Setup::kEyeInHand, stations, d));
      hecal::sim::ProtocolOptions protocol;
      protocol.stations = stations;
      DataSet set;
      set.data = hecal::sim::SimulateThesisProtocol(protocol, noise, noise, rng);
      set.problem = set.data.MeasuredProblem();
#ifdef HECAL_HAVE_OPENCV_PEERS
      set.opencv = hecal::peers::PrepareOpenCvInput(set.problem);
#endif
      sets.push_back(std::move(set));
    }
  }
  return sets;
}

using Solver = std::function<Pose(const DataSet&)>;

void RunSolver(benchmark::State& state, const Solver& solve, int stations, bool judge) {
  const std::vector<DataSet>& sets = DataSets(stations);
  double rotation_sq = 0.0, translation_sq = 0.0, worst_rotation = 0.0, worst_translation = 0.0;
  int finite = 0, failures = 0;
  for (const DataSet& set : sets) {
    try {
      const Pose X = solve(set);
      if (!X.matrix().allFinite()) {
        ++failures;
        continue;
      }
      const hecal::study::RotationTranslation e = hecal::study::PoseError(X, set.data.X);
      rotation_sq += e.rotation * e.rotation;
      translation_sq += e.translation * e.translation;
      worst_rotation = std::max(worst_rotation, e.rotation);
      worst_translation = std::max(worst_translation, e.translation);
      ++finite;
      if (e.rotation * kDeg > 10.0) ++failures;
    } catch (const std::exception&) {
      ++failures;
    }
  }
  if (judge && (finite < kDataSets || worst_rotation * kDeg > 1.0 || worst_translation > 0.01)) {
    state.SkipWithError("wrong result: error above 1 deg / 10 mm, or a failed solve");
    return;
  }
  size_t next = 0;
  for (auto _ : state) {
    const DataSet& set = sets[next];
    next = (next + 1) % sets.size();
    try {
      Pose X = solve(set);
      benchmark::DoNotOptimize(X);
    } catch (const std::exception&) {
      benchmark::ClobberMemory();
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  state.counters["rot_err_deg"] = finite > 0 ? std::sqrt(rotation_sq / finite) * kDeg : nan;
  state.counters["trans_err_mm"] = finite > 0 ? std::sqrt(translation_sq / finite) * 1e3 : nan;
  state.counters["failures"] = failures;
}

Solver HecalSolver(handeye::Method method) {
  if (handeye::Info(method).closed_form) {
    return [method](const DataSet& set) { return handeye::SolveClosedForm(method, set.problem).X; };
  }
  hecal::estimation::CalibrateOptions options;
  options.method = method;
  options.robot_sigma = hecal::estimation::PoseSigma{kSigmaRotation, kSigmaTranslation};
  options.camera_sigma = options.robot_sigma;
  // The solve only, like the closed forms and OpenCV (strobl's default UT covariance would add
  // 24n + 1 solves).
  options.covariance.method = hecal::estimation::CovarianceMethod::kNone;
  return [options](const DataSet& set) {
    return hecal::estimation::Calibrate(set.problem, options).X;
  };
}

Solver GoodStartMlSolver() {
  hecal::estimation::CalibrateOptions options;
  options.robot_sigma = hecal::estimation::PoseSigma{kSigmaRotation, kSigmaTranslation};
  options.camera_sigma = options.robot_sigma;
  return [options](const DataSet& set) {
    hecal::estimation::CalibrationResult start;
    start.method = handeye::Method::kMl;
    start.X = set.data.X;
    start.Z = set.data.Z;
    start.robot_sigma = *options.robot_sigma;
    start.camera_sigma = *options.camera_sigma;
    return hecal::estimation::Resolve(set.problem, start, options).X;
  };
}

void RegisterAll() {
  for (const handeye::MethodInfo& info : handeye::AllMethods()) {
    for (int n : {10, 20, 50}) {
      const std::string suffix = std::string(info.name) + "/" + std::to_string(n);
      const handeye::Method method = info.method;
      benchmark::RegisterBenchmark(("hecal/" + suffix).c_str(), [method,
                                                                 n](benchmark::State& state) {
        RunSolver(state, HecalSolver(method), n, /*judge=*/true);
      })->Unit(benchmark::kMicrosecond);
      if (method == handeye::Method::kMl) {
        benchmark::RegisterBenchmark(("hecal/ml-good-start/" + std::to_string(n)).c_str(),
                                     [n](benchmark::State& state) {
                                       RunSolver(state, GoodStartMlSolver(), n, /*judge=*/true);
                                     })
            ->Unit(benchmark::kMicrosecond);
      }
#ifdef HECAL_HAVE_OPENCV_PEERS
      if (hecal::peers::HasOpenCvPeer(method)) {
        benchmark::RegisterBenchmark(("opencv/" + suffix).c_str(), [method,
                                                                    n](benchmark::State& state) {
          const Solver solve = [method](const DataSet& set) {
            return hecal::peers::SolveWithOpenCv(method, set.opencv, /*estimate_z=*/false).X;
          };
          RunSolver(state, solve, n, /*judge=*/false);
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
