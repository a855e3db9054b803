// `hecal calibrate --images`: see calibrate.h.
#include "calibrate.h"
#include "hecal/hecal.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "conventions.h"
#include "job_output.h"
#endif

namespace hecal::cli {

#if defined(HECAL_HAVE_OPENCV_PEERS)
void RunCalibrateImages(const CalibrateFlags& flags, const CalibrateSettings& settings,
                        const Io& io) {
  if (settings.all) {
    throw InputError("--method", 0, "--method all is not available with --images",
                     "run hecal detect to write camera.csv, then hecal calibrate --camera "
                     "camera.csv --method all; or give one method");
  }
  if (settings.options.covariance.method == estimation::CovarianceMethod::kUnscented) {
    throw InputError("--covariance", 0,
                     "--covariance unscented is not available with --images (its input is the "
                     "noise of every detected pixel: thousands of sigma points)",
                     "use linear (the default) or montecarlo; or run hecal detect and "
                     "calibrate --camera camera.csv --covariance unscented on the poses");
  }
  if (flags.camera_inverse) {
    throw InputError("--camera-inverse", 0, "applies to --camera files only",
                     "leave it out: poses from --images are T_camera_target");
  }
  if (flags.target.empty()) {
    throw InputError("--target", 0, "--images needs --target",
                     "give the target description, e.g. --target target.yaml (docs/targets.md)");
  }
  if (flags.target == "none") {
    throw InputError("--target", 0,
                     "--target none (generic image features, no target) works with --method "
                     "global only: the other methods need the target's poses",
                     "add --method global, or give the target with --target target.yaml");
  }
  jobs::ImageFolderCalibrationOptions options;
  options.images = {flags.images, flags.target, flags.intrinsics,
                    settings.options.covariance.threads};
  options.robot = flags.robot;
  options.robot_read = settings.read;
  options.robot_read.invert = flags.robot_inverse;
  options.setup = settings.setup;
  options.calibration.calibrate = settings.options;
  options.calibration.pixel_sigma = ParsePixelSigma(flags.pixel_sigma);
  options.calibration.refine_intrinsics = flags.refine_intrinsics;
  options.words = ConventionFlagWords();
  options.caller = "hecal calibrate";
  const jobs::ImageFolderCalibration result =
      jobs::CalibrateFromImageFolder(options, PrintingCallbacks(io));
  report::PrintImageResultSummary(io.out, result.document, result.camera);
  WriteCalibrateOutputs(flags, options.robot_read, result.document, io);
}

#else

void RunCalibrateImages(const CalibrateFlags&, const CalibrateSettings&, const Io&) {
  throw InputError("hecal calibrate --images", 0,
                   "this hecal was built without the vision layer (OpenCV)",
                   "rebuild with -DHECAL_BUILD_VISION=ON, or give --camera camera.csv");
}

#endif

}  // namespace hecal::cli
