// The study results as text tables (what `hecal simulate` and `hecal bench` print;
// docs/thesis-study.md, docs/bench.md). Cells: text_table.h.
//
// Study (study/study.h), one block per setting: a title line (setup, stations, noise kind and
// where, sigma in mm / deg, trials, robot noise scale, gross outliers), the first-order bound of
// ml at the truth, then one line per method: failures, outliers (triangle threshold), and the
// median, RMSE, 10th and 90th percentile and maximum of X's rotation error (degrees) and
// translation error (mm). With predicted covariances: one consistency line per method (mean
// NEES against its 95% band, 1σ / 2σ coverage, predicted over empirical sd per axis) and one
// for the model-only covariance. With gross outliers or outlier rejection: one line per method
// with the outliers found, the trials where all were found, the good stations rejected, and the
// RMSE of the clean reference with the ratio to it.
//
// Benchmark (study/bench.h): a title line (setup, noise level, data sets, seed), then per method
// and station count hecal's time per solve, the peer's, the speed-up (peer time / hecal time),
// and each implementation's RMS error of X (degrees, mm) and failures; then ml from a good
// start against ml from the closed-form starts.
#pragma once

#include <ostream>

#include "hecal/study/bench.h"
#include "hecal/study/study.h"

namespace hecal::report {

void PrintStudyTable(std::ostream& out, const study::StudyResult& result);

void PrintBenchTable(std::ostream& out, const study::BenchResult& result);

}  // namespace hecal::report
