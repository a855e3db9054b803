// `hecal calibrate --streams` (docs/streams.md, docs/cli.md#hecal-calibrate): see calibrate.h.
#include <string>

#include "calibrate.h"
#include "hecal/hecal.h"
#include "job_output.h"

namespace hecal::cli {

namespace {

// The flags of the stream form as the job's options.
jobs::StreamCalibrationOptions StreamFlags(const CalibrateFlags& flags,
                                           const CalibrateSettings& settings) {
  jobs::StreamCalibrationOptions options;
  options.files = PoseFileOptions(flags, settings);
  options.streams.time_offset = flags.time_offset;
  options.streams.window = flags.time_offset_window;
  options.streams.rules.max_gap = flags.max_gap;
  const estimation::PoseSigma speed = ParseSigma("--max-speed", flags.max_speed);
  options.streams.rules.max_angular_speed = speed.rotation;
  options.streams.rules.max_linear_speed = speed.translation;
  options.streams.rules.max_stations = flags.stations;
  return options;
}

report::ResultDocument CalibrateStreamForm(const CalibrateFlags& flags,
                                           const CalibrateSettings& settings, const Io& io) {
  if (flags.images.empty()) return jobs::CalibrateFromStreams(StreamFlags(flags, settings));
#if defined(HECAL_HAVE_OPENCV_PEERS)
  jobs::ImageStreamCalibrationOptions options;
  options.streams = StreamFlags(flags, settings);
  options.detection.images = {flags.images, flags.target, flags.intrinsics,
                              settings.options.covariance.threads, vision::ImageUse::kPoses};
  options.detection.output = flags.images;
  options.detection.caller = "hecal calibrate --streams --images";
  options.stamps = flags.stamps;
  return jobs::CalibrateFromImageStream(options, PrintingCallbacks(io));
#else
  (void)io;
  throw InputError("hecal calibrate --streams --images", 0,
                   "this hecal was built without the vision layer (OpenCV)",
                   "rebuild with -DHECAL_BUILD_VISION=ON, or give a camera stream with --camera");
#endif
}

}  // namespace

void RunCalibrateStreams(const CalibrateFlags& flags, const CalibrateSettings& settings,
                         const Io& io) {
  if (!flags.stamps.empty() && flags.images.empty()) {
    throw InputError("--stamps", 0, "--stamps stamps the images of --images",
                     "give --images DIR with it, or leave it out (a camera stream has its own "
                     "stamp column)");
  }
  const report::ResultDocument document = CalibrateStreamForm(flags, settings, io);
  PrintCalibrateSummaries(document, io);
  report::PrintStreamSummary(io.out, document);
  // The report's 3D scene reads robot poses by station id from a table; a stream's stations are
  // interpolated, so the scene shows the base and the fixed frame only.
  WriteCalibrateOutputs(flags, {}, document, io);
}

}  // namespace hecal::cli
