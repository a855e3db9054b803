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
// The flags bind into study::BenchOptions; the protocol (data, solvers, the good start of ml,
// accuracy, CPU-time timing) is study::RunBench (study/bench.h), with OpenCV's hand-eye functions
// (peers/opencv_handeye.h) as its peer when vision is built (without it only hecal rows are
// produced). A bad value is an InputError naming the flag (BenchOptions::IsValid, field_flags.h).
// --json prints report::BenchJson (report/bench_file.h). The table (report/study_text.h) shows both
// implementations side by side and the speed-up OpenCV time / hecal time; below it one line per
// station count for ml from a good start, with its speed-up over ml from the closed-form starts.
#pragma once

#include "cli.h"

// RegisterBenchCommand (cli.h) adds the subcommand.
