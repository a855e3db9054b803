// Calibration from paired poses as one job (`hecal calibrate --robot R --camera C`, docs/README.md
// "The data flow of hecal calibrate", steps 4–8): one selection of stations for every method
// (estimation/station_selection.h), then estimation::Calibrate with the method of the options,
// or with every method (`--method all`), each result's warnings preceded by the caller's notes
// and followed by the plausibility warnings (estimation/plausibility.h). The returned
// ResultDocument is what report::WriteResult writes (docs/result-file.md). Frames and units: those
// of the problem (handeye/problem.h; metres, radians); `unit` only labels the document.
//
// Errors: with one method, its hecal::DegenerateError; with every method, a method that refuses
// the data is recorded in ResultDocument::failures and the others go on — when all refuse, the
// first refusal is thrown; a result that is not finite (X, Z, the residual RMS or the
// covariance) is a DegenerateError naming the likely cause (CheckFiniteResult). InputErrors of
// the options pass through.
#pragma once

#include <string>
#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/plausibility.h"
#include "hecal/handeye/problem.h"
#include "hecal/io/units.h"
#include "hecal/report/result_file.h"

namespace hecal::report {

struct PoseCalibrationInput {
  handeye::Problem problem;
  io::LengthUnit unit = io::LengthUnit::kMetre;  // the document's output unit
  std::vector<std::string> station_ids;          // one per station of the problem
  estimation::PlausibilityInput plausibility;
  std::vector<std::string> notes;  // put first in every result's warnings
};

// Runs the job above; `all_methods` runs every method of estimation::AllMethods().
ResultDocument CalibrateFromPoses(const PoseCalibrationInput& input,
                                  estimation::CalibrateOptions options, bool all_methods);

// A result about to be printed and written: X, Z, the residual RMS and the covariance must be
// finite (README "Reliability"); DegenerateError otherwise.
void CheckFiniteResult(const estimation::CalibrationResult& result);

}  // namespace hecal::report
