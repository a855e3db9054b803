// `hecal bench`: see bench.h.
#include "bench.h"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>

#include "bounds.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/report/bench_file.h"
#include "hecal/study/bench.h"
#include "hecal/study/study_csv.h"
#include "list_flags.h"
#ifdef HECAL_HAVE_OPENCV_PEERS
#include "hecal/peers/opencv_handeye.h"
#endif

namespace hecal::cli {
namespace {

using study::BenchRow;
using study::BenchStart;

constexpr double kDeg = 180.0 / std::numbers::pi;

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

// The noise level as typed: "n" when millimetres and degrees agree, else "MM/DEG".
std::string LevelText(const study::NoiseLevel& sigma) {
  return sigma.mm == sigma.deg
             ? study::FormatNumber(sigma.mm)
             : study::FormatNumber(sigma.mm) + "/" + study::FormatNumber(sigma.deg);
}

void PrintTable(const study::BenchResult& result, const Io& io) {
  const study::BenchOptions& o = result.options;
  const std::vector<BenchRow>& rows = result.rows;
  io.out << "hecal bench: thesis protocol, " << handeye::SetupName(o.setup) << ", Gaussian noise "
         << LevelText(o.sigma) << " (mm/deg) on robot and camera, " << o.datasets
         << " data sets per station count, seed " << o.seed
         << "; errors of X are RMS over data sets; fail = threw, "
            "non-finite or > 10 deg\n";
  io.out << Pad("method", 18, true) << Pad("n", 4) << Pad("hecal us", 12) << Pad("opencv us", 12)
         << Pad("speed-up", 10) << Pad("hecal deg", 11) << Pad("hecal mm", 10) << Pad("fail", 5)
         << Pad("opencv deg", 12) << Pad("opencv mm", 11) << Pad("fail", 5) << "\n";
  for (const BenchRow& row : rows) {
    if (row.impl != "hecal" || row.start == BenchStart::kGood) continue;
    const BenchRow* peer = nullptr;
    for (const BenchRow& other : rows) {
      if (other.impl == "opencv" && other.method == row.method && other.stations == row.stations) {
        peer = &other;
      }
    }
    io.out << Pad(std::string(handeye::Info(row.method).name), 18, true)
           << Pad(std::to_string(row.stations), 4) << Pad(Format("%.2f", row.us_per_solve), 12)
           << Pad(peer ? Format("%.2f", peer->us_per_solve) : "-", 12)
           << Pad(peer ? Format("%.1fx", peer->us_per_solve / row.us_per_solve) : "-", 10)
           << Pad(ErrorText(row.accuracy.rotation_error, kDeg), 11)
           << Pad(ErrorText(row.accuracy.translation_error, 1000.0), 10)
           << Pad(std::to_string(row.accuracy.failures), 5)
           << Pad(peer ? ErrorText(peer->accuracy.rotation_error, kDeg) : "-", 12)
           << Pad(peer ? ErrorText(peer->accuracy.translation_error, 1000.0) : "-", 11)
           << Pad(peer ? std::to_string(peer->accuracy.failures) : "-", 5) << "\n";
  }
  io.out << "speed-up = OpenCV time / hecal time (> 1: hecal is faster)\n";
  for (const BenchRow& row : rows) {
    if (row.start != BenchStart::kGood) continue;
    const BenchRow* multi = nullptr;
    for (const BenchRow& other : rows) {
      if (other.start == BenchStart::kClosedForm && other.method == row.method &&
          other.stations == row.stations) {
        multi = &other;
      }
    }
    io.out << handeye::Info(row.method).name << " from a good start, n = " << row.stations << ": "
           << Format("%.2f", row.us_per_solve) << " us per solve"
           << (multi ? Format(", %.1fx faster than from the closed-form starts",
                              multi->us_per_solve / row.us_per_solve)
                     : std::string())
           << " (X " << ErrorText(row.accuracy.rotation_error, kDeg) << " deg / "
           << ErrorText(row.accuracy.translation_error, 1000.0) << " mm, " << row.accuracy.failures
           << " fail)\n";
  }
}

#ifdef HECAL_HAVE_OPENCV_PEERS
// OpenCV's hand-eye functions on inputs converted once per data set (outside the timing),
// without computing Z for calibrateHandEye.
std::optional<study::BenchPeer> OpenCvPeer() {
  study::BenchPeer peer;
  peer.name = "opencv";
  peer.prepare =
      [](handeye::Method method,
         const std::vector<study::BenchDataSet>& sets) -> std::optional<study::BenchSolver> {
    if (!peers::HasOpenCvPeer(method)) return std::nullopt;
    auto inputs = std::make_shared<std::vector<peers::OpenCvInput>>();
    for (const study::BenchDataSet& set : sets) {
      inputs->push_back(peers::PrepareOpenCvInput(set.problem));
    }
    return [method, inputs](std::size_t i) {
      return peers::SolveWithOpenCv(method, (*inputs)[i], /*estimate_z=*/false).X;
    };
  };
  return peer;
}
#else
std::optional<study::BenchPeer> OpenCvPeer() {
  return std::nullopt;
}
#endif

struct BenchCommand {
  study::BenchOptions options;
  bool json = false;
};

void RunBench(const BenchCommand& command, const Io& io) {
  std::string why;
  if (!command.options.IsValid(&why)) throw OptionsError(why);
  const study::BenchResult result = study::RunBench(command.options, OpenCvPeer());
  if (command.json) {
    io.out << report::BenchJson(result);
  } else {
    PrintTable(result, io);
  }
}

}  // namespace

void RegisterBenchCommand(CLI::App& app, const Io& io) {
  auto command = std::make_shared<BenchCommand>();
  study::BenchOptions& o = command->options;
  CLI::App* bench =
      app.add_subcommand("bench", "Time hecal's solvers and OpenCV's on identical generated data");
  AddWholeNumberList(*bench, "--stations", o.stations,
                     "Station counts, comma separated (3 to 100000)")
      ->default_str("10,20,50");
  bench->add_flag("--json", command->json, "Print one JSON array (docs/bench.md)");
  bench
      ->add_option_function<std::string>(
          "--method",
          [&o](const std::string& text) { o.methods = ParseMethodList("--method", text); },
          "Method name(s), comma separated, or all")
      ->default_str("all");
  bench
      ->add_option_function<std::string>(
          "--setup",
          [&o](const std::string& text) {
            const std::optional<handeye::Setup> setup = handeye::ParseSetup(text);
            if (!setup) {
              throw InputError("--setup", 0, "unknown setup '" + text + "'",
                               "use eye-in-hand or eye-to-hand");
            }
            o.setup = *setup;
          },
          "eye-in-hand | eye-to-hand")
      ->default_str("eye-in-hand");
  AddWholeNumber(*bench, "--datasets", o.datasets, "Data sets per station count (1 to 10000)")
      ->capture_default_str();
  bench
      ->add_option_function<std::string>(
          "--sigma",
          [&o](const std::string& text) {
            o.sigma = ParseNoiseLevel("--sigma", text, '/', /*single=*/true);
          },
          "Noise on both: n (mm and deg) or MM/DEG")
      ->default_str("0.1");
  bench->add_option("--min-time", o.min_time, "Timing budget per row, seconds (0 to 3600)")
      ->capture_default_str();
  AddWholeNumber(*bench, "--seed", o.seed, "Random seed (0 to 2^64-1)")->capture_default_str();
  bench->callback([command, io] { RunBench(*command, io); });
}

}  // namespace hecal::cli
