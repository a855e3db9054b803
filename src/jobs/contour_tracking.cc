// A contour tracked through a folder of images: see contour_tracking.h.
#include "hecal/jobs/contour_tracking.h"

#include <vector>

#include "hecal/contour/bspline.h"
#include "hecal/core/options_check.h"
#include "hecal/io/contour_file.h"
#include "hecal/vision/contour_images.h"

namespace hecal::jobs {

bool ContourTrackingOptions::IsValid(std::string* why) const {
  if (images.empty()) {
    return Invalid(why, "ContourTrackingOptions.images", "is empty",
                   "give the folder that holds the image sequence");
  }
  if (init.empty()) {
    return Invalid(why, "ContourTrackingOptions.init", "is empty",
                   "give the contour file of the first image (x,y in px)");
  }
  return tracking.IsValid(why);
}

report::ContourTrack TrackContourImages(
    const ContourTrackingOptions& options, const JobCallbacks& callbacks,
    const std::function<void(const contour::TrackedImage&)>& on_frame) {
  RequireValid(options);
  contour::SequenceTrackingOptions tracking = options.tracking;
  tracking.perspective = options.perspective.value_or(options.principal.has_value());
  tracking.control = io::ReadContourFile(options.init);
  if (options.init_on_curve) {
    tracking.control = contour::ClosedBSpline::Interpolating(tracking.control).control_points();
  }
  tracking.principal = options.principal.value_or(tracking.control.rowwise().mean());
  contour::SequenceTracker tracker(tracking);
  callbacks.Progress(
      tracking.perspective
          ? "pose model: perspective (weak-perspective bias removed, principal point given)\n"
          : "pose model: weak perspective (the contour paper's; give --principal-point for "
            "perspective)\n");
  std::vector<contour::TrackedImage> frames =
      vision::TrackImageSequence(options.images, &tracker, on_frame);
  return {tracking, tracker.tracker().template_shape(), tracker.tracker().polarity(),
          std::move(frames)};
}

}  // namespace hecal::jobs
