// `hecal simulate`: the thesis study (docs/thesis-study.md) on hecal's solvers, side by side.
//
//   hecal simulate [--setup eye-in-hand|eye-to-hand[,...]]      default eye-in-hand
//                  [--stations N[,N...]]                        default 3,5,10,15,20
//                  [--trials N]                                 default 200
//                  [--noise-on robot|camera|both[,...]]         default both
//                  [--noise gaussian|uniform|systematic[,...]]  default gaussian
//                  [--sigma LEVEL[,LEVEL...]]                   default 0,0.3,1
//                  [--method NAME[,NAME...]|all]                default all
//                  [--seed N] [--threads N]                     default 1, 0 (= every core)
//                  [--covariance none|default|linear|unscented|montecarlo]  default none
//                  [--covariance-samples N]                     default 1000 (montecarlo)
//                  [--outliers K[,K...]] [--reject-outliers]    default 0, off
//                  [--output trials.csv] [--summary summary.csv]
// Every list flag is a sweep; the study runs the Cartesian product (setup × noise-on × noise ×
// sigma × stations). A noise LEVEL is either one number n — n mm on each translation component
// and n degrees on each rotation component, the thesis' "n mm / n°" — or MM/DEG for different
// values (e.g. 0.2/0.05). For uniform noise the level is the half-width (±n); for systematic
// noise it is the constant offset per component.
// Stations count poses (the thesis' k motions are k + 1 stations); at least 3.
// --covariance: each trial also predicts the covariance of X that way (default: each
// method's own default, estimation::DefaultCovarianceMethod) with the setting's noise model,
// and the table and summary gain consistency columns: mean NEES with its 95% χ² band, 1σ/2σ
// coverage, predicted/empirical standard deviation per axis (study.h).
// --outliers K (a sweep too): K stations per data set get a random robot pose
// (sim/gross_outliers.h); each method also solves the data set without them (the reference).
// --reject-outliers: every method runs through calibrate's outlier rejection
// (estimation/station_selection.h); the table and summary then report the fraction of gross
// outliers found, of good stations rejected, and the RMSE against the reference.
// The flags bind into study::SimulateOptions (study/simulate.h; list flags parsed once here),
// whose IsValid checks every range (stations, outliers, trials, settings, trial rows, sigmas,
// robot scales, threads, samples); a bad value is an InputError naming the flag (field_flags.h,
// exit 2, one line on stderr). study::Simulate runs the study; this command prints the seed and
// a table per setting (stdout, report/study_text.h); --output and --summary write the CSV files of
// study/study_csv.h, both or neither (io/atomic_file.h; the paths are checked before the study
// runs).
#pragma once

#include "cli.h"

// RegisterSimulateCommand (cli.h) adds the subcommand.
