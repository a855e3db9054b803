// Calibration from paired poses as one job: see pose_calibration.h.
#include "hecal/report/pose_calibration.h"

#include <cmath>
#include <exception>

#include "hecal/core/error.h"
#include "hecal/estimation/methods.h"
#include "hecal/estimation/station_selection.h"

namespace hecal::report {

void CheckFiniteResult(const estimation::CalibrationResult& result) {
  const bool finite = result.X.matrix().allFinite() && result.Z.matrix().allFinite() &&
                      std::isfinite(result.rotation_rms) && std::isfinite(result.translation_rms) &&
                      (!result.covariance || result.covariance->covariance.allFinite());
  if (!finite) {
    throw DegenerateError("X and Z: the solution is not finite",
                          "check the poses' values and units (lengths far beyond a robot's "
                          "reach overflow the solver)");
  }
}

ResultDocument CalibrateFromPoses(const PoseCalibrationInput& input,
                                  estimation::CalibrateOptions options, bool all_methods) {
  ResultDocument document;
  document.setup = input.problem.setup;
  document.unit = input.unit;
  document.station_ids = input.station_ids;
  document.all_methods = all_methods;
  options.station_ids = input.station_ids;
  // One selection of stations for every method.
  const estimation::StationSelection selection =
      estimation::SelectStationsFor(input.problem, options);
  document.rejected = selection.Rejected();
  if (all_methods) {
    // Degenerate data stop every method: then the first error is the answer. A method that
    // refuses data the others accept is reported and skipped.
    std::exception_ptr first_error;
    for (const estimation::MethodInfo& info : estimation::AllMethods()) {
      options.method = info.method;
      try {
        document.results.push_back(estimation::Calibrate(input.problem, options, selection));
      } catch (const DegenerateError& error) {
        if (!first_error) first_error = std::current_exception();
        document.failures.push_back({info.method, error.what()});
      }
    }
    if (document.results.empty()) std::rethrow_exception(first_error);
  } else {
    document.results.push_back(estimation::Calibrate(input.problem, options, selection));
  }
  for (estimation::CalibrationResult& result : document.results) {
    std::vector<std::string> notes = input.notes;
    for (std::string& warning : estimation::PlausibilityWarnings(input.plausibility, result)) {
      notes.push_back(std::move(warning));
    }
    result.warnings.insert(result.warnings.begin(), notes.begin(), notes.end());
  }
  for (const estimation::CalibrationResult& result : document.results) CheckFiniteResult(result);
  return document;
}

}  // namespace hecal::report
