// `hecal simulate --pivot` (docs/pivot.md#the-study): the pivot study of jobs/pivot_study.h on
// simulate's --sigma, --stations, --trials and --seed (defaults 0.1, 20 and 200 when not given),
// with its own --max-tilt; optionally writes one synthetic pose file (--write-pivot) that
// `hecal pivot` calibrates back.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli {

struct PivotStudyFlags {
  bool pivot = false;       // --pivot
  double max_tilt = 30.0;   // --max-tilt DEG
  std::string write_pivot;  // --write-pivot FILE: trial 0 of the first setting as a pose table
};

// Adds --pivot and the flags that only it reads to `simulate`.
void AddPivotStudyFlags(CLI::App& simulate, PivotStudyFlags& flags);

// What `simulate` was given for the pivot study: its options and whether --sigma, --stations and
// --trials were on the command line (else the pivot study's defaults).
struct PivotStudyInput {
  const jobs::SimulateOptions& simulate;
  bool sigma_given = false;
  bool stations_given = false;
  bool trials_given = false;
};

// Runs the study and prints its table (RMSE of the tip and the pivot, mean NEES with its 95% band,
// the tip's NEES, 1σ / 2σ coverage, per fit told the noise and estimating it).
void RunSimulatePivot(const PivotStudyInput& input, const PivotStudyFlags& flags, const Io& io);

}  // namespace hecal::cli
