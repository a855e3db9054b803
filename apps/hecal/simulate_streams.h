// `hecal simulate --streams` (docs/streams.md#the-study): the stream study of
// jobs/stream_study.h on simulate's setups, noise levels, trials, seed and threads, with its own
// flags for the recordings; optionally writes the first trial's streams as pose files.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli {

struct StreamStudyFlags {
  bool streams = false;      // --streams
  bool sigma_given = false;  // --sigma was given (else 1 mm / 1 deg)
  jobs::StreamStudyOptions options;
  std::string write_streams;  // --write-streams DIR: robot.csv, camera.csv, truth.json
};

// Adds --streams and the flags that only it reads to `simulate`.
void AddStreamStudyFlags(CLI::App& simulate, StreamStudyFlags& flags);

// Runs the study with simulate's options (setups, sigmas, noise kind, trials, seed, threads,
// estimate_noise); --output and --summary get the per-trial CSV and the summary text.
void RunSimulateStreams(const jobs::SimulateOptions& simulate, StreamStudyFlags flags,
                        const std::string& output, const std::string& summary, const Io& io);

}  // namespace hecal::cli
