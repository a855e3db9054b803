// `hecal calibrate --streams` (docs/streams.md, docs/cli.md#hecal-calibrate): see calibrate.h.
#include <string>

#include "calibrate.h"
#include "hecal/hecal.h"

namespace hecal::cli {

void RunCalibrateStreams(const CalibrateFlags& flags, const CalibrateSettings& settings,
                         const Io& io) {
  jobs::StreamCalibrationOptions options;
  options.files = PoseFileOptions(flags, settings);
  options.streams.time_offset = flags.time_offset;
  options.streams.window = flags.time_offset_window;
  options.streams.rules.max_gap = flags.max_gap;
  const estimation::PoseSigma speed = ParseSigma("--max-speed", flags.max_speed);
  options.streams.rules.max_angular_speed = speed.rotation;
  options.streams.rules.max_linear_speed = speed.translation;
  options.streams.rules.max_stations = flags.stations;
  const report::ResultDocument document = jobs::CalibrateFromStreams(options);
  PrintCalibrateSummaries(document, io);
  report::PrintStreamSummary(io.out, document);
  // The report's 3D scene reads robot poses by station id from a table; a stream's stations are
  // interpolated, so the scene shows the base and the fixed frame only.
  WriteCalibrateOutputs(flags, {}, document, io);
}

}  // namespace hecal::cli
