// `hecal calibrate --streams` (docs/streams.md, docs/cli.md#hecal-calibrate): see calibrate.h.
#include <string>

#include "calibrate.h"
#include "conventions.h"
#include "hecal/hecal.h"

namespace hecal::cli {

void RunCalibrateStreams(const CalibrateFlags& flags, const CalibrateSettings& settings,
                         const Io& io) {
  jobs::StreamCalibrationOptions options;
  jobs::PoseFileCalibrationOptions& files = options.files;
  files.robot = flags.robot;
  files.camera = flags.camera;
  files.robot_read = settings.read;
  files.robot_read.invert = flags.robot_inverse;
  files.camera_read = settings.read;
  files.camera_read.invert = flags.camera_inverse;
  files.setup = settings.setup;
  files.calibrate = settings.options;
  files.all_methods = settings.all;
  files.words = ConventionFlagWords();
  files.file_words = {"--robot", "--camera"};
  options.streams.time_offset = flags.time_offset;
  options.streams.window = flags.time_offset_window;
  options.streams.rules.max_gap = flags.max_gap;
  const estimation::PoseSigma speed = ParseSigma("--max-speed", flags.max_speed);
  options.streams.rules.max_angular_speed = speed.rotation;
  options.streams.rules.max_linear_speed = speed.translation;
  options.streams.rules.max_stations = flags.stations;
  const report::ResultDocument document = jobs::CalibrateFromStreams(options);
  for (size_t k = 0; k < document.results.size(); ++k) {
    if (k > 0) io.out << "\n";
    report::PrintResultSummary(io.out, document, document.results[k]);
  }
  if (settings.all) report::PrintMethodComparison(io.out, document);
  report::PrintStreamSummary(io.out, document);
  // The report's 3D scene reads robot poses by station id from a table; a stream's stations are
  // interpolated, so the scene shows the base and the fixed frame only.
  WriteCalibrateOutputs(flags, {}, document, io);
}

}  // namespace hecal::cli
