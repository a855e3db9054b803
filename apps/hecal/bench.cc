// `hecal bench`: see bench.h.
#include "bench.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <random>

#include "bounds.h"
#include "hecal/core/error.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/calibration_covariance.h"
#include "hecal/io/delimited_text.h"
#include "hecal/sim/thesis_protocol.h"
#include "hecal/study/study.h"
#include "list_flags.h"
#ifdef HECAL_HAVE_OPENCV_PEERS
#include "hecal/peers/opencv_handeye.h"
#endif

namespace hecal::cli {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kFailureDeg = 10.0;

// Every timed solve writes here, so the optimiser cannot drop it.
volatile double g_sink = 0.0;

// CPU time of the whole process (every thread): unlike wall time it does not count other
// programs sharing the cores, and it still counts any worker threads a library starts.
double ProcessCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

struct DataSet {
  sim::SimulatedData data;
  handeye::Problem problem;
#ifdef HECAL_HAVE_OPENCV_PEERS
  peers::OpenCvInput opencv;
#endif
};

// How strobl and ml start: from every closed-form solution, or from one good start.
enum class Start { kNotApplicable, kMulti, kGood };

struct Row {
  std::string impl;
  handeye::Method method;
  Start start;
  int stations;
  double us_per_solve;
  std::optional<double> rotation_error;     // radians, RMS over finite solves
  std::optional<double> translation_error;  // metres
  int failures;
  int datasets;
};

// Solves data set d, returns X.
using Solver = std::function<Pose(const DataSet&)>;

Row Measure(const std::string& impl, handeye::Method method, Start start, int stations,
            const std::vector<DataSet>& sets, const Solver& solve, double min_time) {
  Row row{impl,         method, start,
          stations,     0.0,    std::nullopt,
          std::nullopt, 0,      static_cast<int>(sets.size())};
  double rotation_sq = 0.0, translation_sq = 0.0;
  int finite = 0;
  for (const DataSet& set : sets) {
    try {
      const Pose X = solve(set);
      if (!X.matrix().allFinite()) {
        ++row.failures;
        continue;
      }
      const study::RotationTranslation error = study::PoseError(X, set.data.X);
      rotation_sq += error.rotation * error.rotation;
      translation_sq += error.translation * error.translation;
      ++finite;
      if (error.rotation * kDeg > kFailureDeg) ++row.failures;
    } catch (const std::exception&) {
      ++row.failures;
    }
  }
  if (finite > 0) {
    row.rotation_error = std::sqrt(rotation_sq / finite);
    row.translation_error = std::sqrt(translation_sq / finite);
  }
  // Timing: whole passes over the data sets until the budget of process CPU time is spent.
  const double begin = ProcessCpuSeconds();
  long solves = 0;
  double elapsed = 0.0;
  do {
    for (const DataSet& set : sets) {
      try {
        g_sink = solve(set).translation()(0);
      } catch (const std::exception&) {
        g_sink = 0.0;
      }
      ++solves;
    }
    elapsed = ProcessCpuSeconds() - begin;
  } while (elapsed < min_time);
  row.us_per_solve = elapsed * 1e6 / static_cast<double>(solves);
  return row;
}

nlohmann::json ToJson(const Row& row, std::uint64_t seed) {
  nlohmann::json object;
  object["impl"] = row.impl;
  object["method"] = std::string(handeye::Info(row.method).name);
  object["start"] = row.start == Start::kNotApplicable ? nlohmann::json(nullptr)
                    : row.start == Start::kMulti       ? nlohmann::json("closed-form")
                                                       : nlohmann::json("good");
  object["stations"] = row.stations;
  object["us_per_solve"] = row.us_per_solve;
  object["rotation_error_deg"] =
      row.rotation_error ? nlohmann::json(*row.rotation_error * kDeg) : nlohmann::json(nullptr);
  object["translation_error"] =
      row.translation_error ? nlohmann::json(*row.translation_error) : nlohmann::json(nullptr);
  object["translation_unit"] = "m";
  object["failures"] = row.failures;
  object["datasets"] = row.datasets;
  object["seed"] = seed;
  return object;
}

std::string Format(const char* format, double value) {
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

std::string Pad(const std::string& text, size_t width, bool left_align = false) {
  if (text.size() >= width) return text;
  const std::string padding(width - text.size(), ' ');
  return left_align ? text + padding : padding + text;
}

std::string ErrorText(const std::optional<double>& value, double scale) {
  if (!value) return "-";
  const double v = *value * scale;
  return v != 0.0 && v < 1e-3 ? Format("%.1e", v) : Format("%.4f", v);
}

void PrintTable(const std::vector<Row>& rows, const BenchFlags& flags, std::uint64_t seed,
                const Io& io) {
  io.out << "hecal bench: thesis protocol, " << flags.setup << ", Gaussian noise " << flags.sigma
         << " (mm/deg) on robot and camera, " << flags.datasets
         << " data sets per station count, seed " << seed
         << "; errors of X are RMS over data sets; fail = threw, "
            "non-finite or > 10 deg\n";
  io.out << Pad("method", 18, true) << Pad("n", 4) << Pad("hecal us", 12) << Pad("opencv us", 12)
         << Pad("speed-up", 10) << Pad("hecal deg", 11) << Pad("hecal mm", 10) << Pad("fail", 5)
         << Pad("opencv deg", 12) << Pad("opencv mm", 11) << Pad("fail", 5) << "\n";
  for (const Row& row : rows) {
    if (row.impl != "hecal" || row.start == Start::kGood) continue;
    const Row* peer = nullptr;
    for (const Row& other : rows) {
      if (other.impl == "opencv" && other.method == row.method && other.stations == row.stations) {
        peer = &other;
      }
    }
    io.out << Pad(std::string(handeye::Info(row.method).name), 18, true)
           << Pad(std::to_string(row.stations), 4) << Pad(Format("%.2f", row.us_per_solve), 12)
           << Pad(peer ? Format("%.2f", peer->us_per_solve) : "-", 12)
           << Pad(peer ? Format("%.1fx", peer->us_per_solve / row.us_per_solve) : "-", 10)
           << Pad(ErrorText(row.rotation_error, kDeg), 11)
           << Pad(ErrorText(row.translation_error, 1000.0), 10)
           << Pad(std::to_string(row.failures), 5)
           << Pad(peer ? ErrorText(peer->rotation_error, kDeg) : "-", 12)
           << Pad(peer ? ErrorText(peer->translation_error, 1000.0) : "-", 11)
           << Pad(peer ? std::to_string(peer->failures) : "-", 5) << "\n";
  }
  io.out << "speed-up = OpenCV time / hecal time (> 1: hecal is faster)\n";
  for (const Row& row : rows) {
    if (row.start != Start::kGood) continue;
    const Row* multi = nullptr;
    for (const Row& other : rows) {
      if (other.start == Start::kMulti && other.method == row.method &&
          other.stations == row.stations) {
        multi = &other;
      }
    }
    io.out << handeye::Info(row.method).name << " from a good start, n = " << row.stations << ": "
           << Format("%.2f", row.us_per_solve) << " us per solve"
           << (multi ? Format(", %.1fx faster than from the closed-form starts",
                              multi->us_per_solve / row.us_per_solve)
                     : std::string())
           << " (X " << ErrorText(row.rotation_error, kDeg) << " deg / "
           << ErrorText(row.translation_error, 1000.0) << " mm, " << row.failures << " fail)\n";
  }
}

// ml re-solved from a good start the way the model check's jackknife and the covariance
// propagation re-solve (estimation::Resolve): from the true X and Z (off the data's optimum by
// about the estimate's own error, as the full estimate is for a jackknife or resampled data set)
// with the sigmas a calibration of the set uses (given, or estimated when --sigma is 0).
Solver GoodStartSolver(const std::vector<DataSet>& sets, const sim::NoiseModel& noise) {
  estimation::CalibrateOptions options;
  options.covariance.method = estimation::CovarianceMethod::kNone;
  options.model_check = false;
  if (!noise.IsZero()) {
    options.robot_sigma = estimation::PoseSigma{noise.rotation_sigma, noise.translation_sigma};
    options.camera_sigma = options.robot_sigma;
  }
  auto starts = std::make_shared<std::vector<estimation::CalibrationResult>>();
  for (const DataSet& set : sets) {
    estimation::CalibrationResult start;  // a set ml cannot calibrate: Resolve fails there too
    start.robot_sigma = options.robot_sigma.value_or(estimation::PoseSigma{});
    start.camera_sigma = start.robot_sigma;
    try {
      start = estimation::Calibrate(set.problem, options);
    } catch (const std::exception&) {
    }
    start.X = set.data.X;
    start.Z = set.data.Z;
    starts->push_back(std::move(start));
  }
  return [starts, options, first = sets.data()](const DataSet& set) {
    return estimation::Resolve(set.problem, (*starts)[static_cast<size_t>(&set - first)], options)
        .X;
  };
}

}  // namespace

void RunBench(const BenchFlags& flags, const Io& io) {
  const std::vector<int> stations =
      ParseIntList("--stations", flags.stations, kMinSimulatedStations, kMaxSimulatedStations);
  const std::vector<handeye::Method> methods = ParseMethodList("--method", flags.method);
  const std::optional<handeye::Setup> setup = handeye::ParseSetup(flags.setup);
  if (!setup) {
    throw InputError("--setup", 0, "unknown setup '" + flags.setup + "'",
                     "use eye-in-hand or eye-to-hand");
  }
  const int datasets = ParseInt("--datasets", flags.datasets, 1, kMaxDatasets,
                                "the number of data sets per station count (e.g. 10)");
  for (int n : stations) {
    if (std::int64_t{n} * datasets > kMaxBenchPoses) {
      throw InputError("--datasets", 0,
                       std::to_string(n) + " stations x " + std::to_string(datasets) +
                           " data sets is more than " + std::to_string(kMaxBenchPoses) +
                           " poses, the most hecal bench generates",
                       "give fewer --datasets or fewer --stations");
    }
  }
  if (!(flags.min_time >= 0.0 && flags.min_time <= kMaxMinTime)) {
    throw InputError("--min-time", 0,
                     "must be 0 to " + io::FormatDouble(kMaxMinTime) + " seconds, got " +
                         io::FormatDouble(flags.min_time),
                     "e.g. --min-time 0.2");
  }
  const std::uint64_t seed = ParseSeed("--seed", flags.seed);
  const SigmaLevel sigma = ParseSigmaLevel("--sigma", flags.sigma);
  CheckNoiseLevel("--sigma", sigma.mm, sigma.deg);
  const sim::NoiseModel noise{sim::NoiseModel::Kind::kGaussian, sigma.deg / kDeg, sigma.mm * 1e-3};

  std::vector<Row> rows;
  for (int n : stations) {
    std::vector<DataSet> sets;
    for (int d = 0; d < datasets; ++d) {
      std::mt19937_64 rng(study::TrialSeed(seed, *setup, n, d));
      sim::ProtocolOptions protocol;
      protocol.setup = *setup;
      protocol.stations = n;
      DataSet set;
      set.data = sim::SimulateThesisProtocol(protocol, noise, noise, rng);
      set.problem = set.data.MeasuredProblem();
#ifdef HECAL_HAVE_OPENCV_PEERS
      set.opencv = peers::PrepareOpenCvInput(set.problem);
#endif
      sets.push_back(std::move(set));
    }
    for (handeye::Method method : methods) {
      Solver hecal_solver;
      if (handeye::Info(method).closed_form) {
        hecal_solver = [method](const DataSet& set) {
          return handeye::SolveClosedForm(method, set.problem).X;
        };
      } else {
        estimation::CalibrateOptions options;
        options.method = method;
        // The solve only, like the closed forms and OpenCV (strobl's default UT covariance
        // would add 24n + 1 solves).
        options.covariance.method = estimation::CovarianceMethod::kNone;
        options.model_check = false;
        if (!noise.IsZero()) {
          options.robot_sigma =
              estimation::PoseSigma{noise.rotation_sigma, noise.translation_sigma};
          options.camera_sigma = options.robot_sigma;
        }
        hecal_solver = [options](const DataSet& set) {
          return estimation::Calibrate(set.problem, options).X;
        };
      }
      const Start start = handeye::Info(method).closed_form ? Start::kNotApplicable : Start::kMulti;
      rows.push_back(Measure("hecal", method, start, n, sets, hecal_solver, flags.min_time));
      if (method == handeye::Method::kMl) {
        rows.push_back(Measure("hecal", method, Start::kGood, n, sets, GoodStartSolver(sets, noise),
                               flags.min_time));
      }
#ifdef HECAL_HAVE_OPENCV_PEERS
      if (peers::HasOpenCvPeer(method)) {
        const Solver opencv_solver = [method](const DataSet& set) {
          return peers::SolveWithOpenCv(method, set.opencv, /*estimate_z=*/false).X;
        };
        rows.push_back(Measure("opencv", method, Start::kNotApplicable, n, sets, opencv_solver,
                               flags.min_time));
      }
#endif
    }
  }

  if (flags.json) {
    nlohmann::json array = nlohmann::json::array();
    for (const Row& row : rows) array.push_back(ToJson(row, seed));
    io.out << array.dump(2) << "\n";
  } else {
    PrintTable(rows, flags, seed, io);
  }
}

void RegisterBenchCommand(CLI::App& app, const Io& io) {
  auto flags = std::make_shared<BenchFlags>();
  CLI::App* bench =
      app.add_subcommand("bench", "Time hecal's solvers and OpenCV's on identical generated data");
  bench->add_option("--stations", flags->stations, "Station counts, comma separated (3 to 100000)")
      ->capture_default_str();
  bench->add_flag("--json", flags->json, "Print one JSON array (docs/bench.md)");
  bench->add_option("--method", flags->method, "Method name(s), comma separated, or all")
      ->capture_default_str();
  bench->add_option("--setup", flags->setup, "eye-in-hand | eye-to-hand")->capture_default_str();
  bench->add_option("--datasets", flags->datasets, "Data sets per station count (1 to 10000)")
      ->capture_default_str();
  bench->add_option("--sigma", flags->sigma, "Noise on both: n (mm and deg) or MM/DEG")
      ->capture_default_str();
  bench->add_option("--min-time", flags->min_time, "Timing budget per row, seconds (0 to 3600)")
      ->capture_default_str();
  bench->add_option("--seed", flags->seed, "Random seed (0 to 2^64-1)")->capture_default_str();
  bench->callback([flags, io] { RunBench(*flags, io); });
}

}  // namespace hecal::cli
