// `hecal bench` (docs/cli.md#hecal-bench, docs/bench.md): binds the flags into
// jobs::BenchOptions, runs jobs::RunBench (study/bench.h) with OpenCV's hand-eye functions
// (jobs/opencv_bench_peer.h) as its peer when vision is built, and prints the table
// (report/study_text.h) or the JSON (report/bench_file.h).
#include <CLI/CLI.hpp>
#include <memory>

#include "bounds.h"
#include "choice_flags.h"
#include "cli.h"
#include "hecal/hecal.h"
#include "list_flags.h"
#ifdef HECAL_HAVE_OPENCV_PEERS
#endif

namespace hecal::cli {
namespace {

struct BenchCommand {
  jobs::BenchOptions options;
  bool json = false;
};

void RunBench(const BenchCommand& command, const Io& io) {
#ifdef HECAL_HAVE_OPENCV_PEERS
  const jobs::BenchResult result = jobs::RunBench(command.options, jobs::OpenCvBenchPeer());
#else
  const jobs::BenchResult result = jobs::RunBench(command.options);
#endif
  if (command.json) {
    io.out << report::BenchJson(result);
  } else {
    report::PrintBenchTable(io.out, result);
  }
}

}  // namespace

void RegisterBenchCommand(CLI::App& app, const Io& io) {
  auto command = std::make_shared<BenchCommand>();
  jobs::BenchOptions& o = command->options;
  CLI::App* bench =
      app.add_subcommand("bench", "Time hecal's solvers and OpenCV's on identical generated data");
  AddWholeNumberList(*bench, "--stations", o.stations,
                     "Station counts, comma separated (3 to 100000)")
      ->default_str("10,20,50");
  bench->add_flag("--json", command->json, "Print one JSON array (docs/bench.md)");
  AddMethodListFlag(*bench, o.methods);
  AddSetupFlag(*bench, o.setup, "eye-in-hand | eye-to-hand")->default_str("eye-in-hand");
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
  AddSeedFlag(*bench, o.seed);
  bench->callback([command, io] { RunBench(*command, io); });
}

}  // namespace hecal::cli
