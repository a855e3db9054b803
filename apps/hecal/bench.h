// `hecal bench`: times every hecal solver and the matching OpenCV 4.6 function on IDENTICAL
// generated data in one process, and reports their errors (docs/bench.md).
//
//   hecal bench [--stations N[,N...]]          default 10,20,50
//               [--json]                       one JSON array instead of the table
//               [--method NAME[,NAME...]|all]  default all (every closed-form solver, strobl, ml)
//               [--setup eye-in-hand|eye-to-hand]  default eye-in-hand
//               [--datasets N]                 data sets per station count, default 10
//               [--sigma LEVEL]                noise on robot and camera, default 0.1 (mm and
//                                              degrees per component; MM/DEG also accepted)
//               [--min-time SECONDS]           timing budget per (impl, method, stations),
//                                              default 0.2
//               [--seed N]                     default 1
// Data: the thesis protocol (sim/thesis_protocol.h) with Gaussian noise on both devices. Each
// solver first solves every data set once for its errors, then repeats passes over all of them
// until --min-time of process CPU time has elapsed; us_per_solve = CPU time / solves (CPU time,
// not wall time, so other programs sharing the machine do not inflate it). hecal's closed-form
// solvers are timed through handeye::SolveClosedForm (observability check, motions, X, and Z),
// strobl and ml through estimation::Calibrate (told the true noise sigmas; their refinement starts
// from every closed-form solution), and ml once more from a good start through estimation::Resolve
// (calibration_covariance.h) — the re-solve the model check's jackknife and the covariance
// propagation run — from the true X and Z with the calibration's sigmas (the truth is off the
// data's optimum by about the estimate's own error, as a calibration's estimate is for its
// jackknife or resampled data sets); OpenCV through
// cv::calibrateHandEye / cv::calibrateRobotWorldHandEye on inputs converted beforehand
// (peers/opencv_handeye.h), without computing Z for calibrateHandEye.
//
// JSON (docs/bench.md), one object per (impl, method, stations):
//   {"impl": "hecal"|"opencv", "method": "park-martin", "start": null|"closed-form"|"good",
//    "stations": 50, "us_per_solve": 12.3,
//    "rotation_error_deg": …, "translation_error": …,
//    "translation_unit": "m", "failures": 0, "datasets": 10}
// rotation_error_deg / translation_error: RMS over the data sets of the error of X against the
// truth (angle of R_true⁻¹ R_est; translation distance in metres), over the solves that returned
// a finite pose (null when none did). failures: data sets where the solver threw, returned a
// non-finite pose, or erred by more than 10°.
// start: null for the closed-form solvers and OpenCV, "closed-form" for strobl and ml from every
// closed-form solution, "good" for ml from a good start (above).
// The table (without --json) shows both implementations side by side and the speed-up
// OpenCV time / hecal time; below it one line per station count for ml from a good start, with
// its speed-up over ml from the closed-form starts. Without HECAL_BUILD_VISION only hecal rows are
// produced.
#pragma once

#include <cstdint>
#include <string>

#include "cli.h"

namespace hecal::cli {

struct BenchFlags {
  std::string stations = "10,20,50";
  bool json = false;
  std::string method = "all";
  std::string setup = "eye-in-hand";
  std::string datasets = "10";  // 1 … 10000 (bounds.h)
  std::string sigma = "0.1";
  double min_time = 0.2;
  std::string seed = "1";  // 0 … 2^64 − 1
};

// Runs the benchmark; throws hecal::InputError for bad flags.
void RunBench(const BenchFlags& flags, const Io& io);

}  // namespace hecal::cli
