// Tracking and rendering contour sequences: see sequence.h.
#include "hecal/contour/sequence.h"

#include <sstream>

#include "hecal/contour/bspline.h"
#include "hecal/contour/perspective_view.h"
#include "hecal/contour/shape_space.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/core/split_mix.h"
#include "hecal/geometry/angle_units.h"

namespace hecal::contour {

std::string_view FrameStatusName(FrameStatus status) {
  switch (status) {
    case FrameStatus::kTracked:
      return "tracked";
    case FrameStatus::kLost:
      return "lost";
    case FrameStatus::kSingular:
      return "singular";
  }
  return "";
}

namespace {

std::string Text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// The options, once IsValid (for the constructor's initialiser list).
const SequenceTrackingOptions& Validated(const SequenceTrackingOptions& options) {
  RequireValid(options);
  return options;
}

}  // namespace

bool SequenceTrackingOptions::IsValid(std::string* why) const {
  if (!camera.IsValid(why)) return false;
  const double range = tracker.search.range;
  if (!(range >= kMinSearchRange && range <= kMaxSearchRange)) {
    return Invalid(why, "EdgeSearchOptions.range", "must be 2 … 200 px, got " + Text(range),
                   "give the largest expected motion of the contour per frame, in pixels");
  }
  if (tracker.measurement_sigma) {
    const double sigma = *tracker.measurement_sigma;
    if (!(sigma > 0.0 && sigma <= kMaxMeasurementSigma)) {
      return Invalid(why, "ShapeTrackerOptions.measurement_sigma",
                     "must be above 0 to 100 px, got " + Text(sigma),
                     "give the edge-location σ in pixels, or leave it to be estimated");
    }
  }
  return tracker.IsValid(why);
}

bool SequenceRenderOptions::IsValid(std::string* why) const {
  if (!camera.IsValid(why)) return false;
  if (frames < 1 || frames > kMaxFrames) {
    return Invalid(why, "SequenceRenderOptions.frames",
                   "must be a whole number from 1 to " + std::to_string(kMaxFrames) + ", got " +
                       std::to_string(frames),
                   "give the number of frames in that range");
  }
  for (const int side : {width, height}) {
    if (side < kMinSide || side > kMaxSide) {
      return Invalid(why, "SequenceRenderOptions.size",
                     "W and H must be whole numbers from " + std::to_string(kMinSide) + " to " +
                         std::to_string(kMaxSide),
                     "give the image size in pixels, e.g. 768,576");
    }
  }
  const std::int64_t pixels = std::int64_t{width} * height;
  if (pixels > kMaxFramePixels || pixels * frames > kMaxSequencePixels) {
    return Invalid(why, "SequenceRenderOptions.size",
                   std::to_string(frames) + " frames of " + std::to_string(width) + "×" +
                       std::to_string(height) + " px are more than " +
                       std::to_string(kMaxFramePixels) + " pixels a frame or " +
                       std::to_string(kMaxSequencePixels) + " in all",
                   "give a smaller size or fewer frames");
  }
  if (!(render.noise_sigma >= 0.0 && render.noise_sigma <= kMaxNoise)) {
    return Invalid(why, "RenderOptions.noise_sigma", "must be 0 … 255 grey levels",
                   "give the noise σ in grey levels (e.g. 3)");
  }
  if (!(render.blur_sigma >= 0.0 && render.blur_sigma <= kMaxBlur)) {
    return Invalid(why, "RenderOptions.blur_sigma", "must be 0 … 20 px",
                   "give the optics blur σ (e.g. 0.7)");
  }
  if (target.cols() < 4) {
    return Invalid(
        why, "SequenceRenderOptions.target",
        "a closed contour needs at least 4 control points, got " + std::to_string(target.cols()),
        "give 4 or more points around the contour");
  }
  return render.IsValid(why);
}

SequenceTracker::SequenceTracker(const SequenceTrackingOptions& options)
    : options_(Validated(options)), tracker_(options.control, options.principal, options.tracker) {
  if (options.perspective) {
    perspective_.emplace(options.control.colwise() - options.principal, options.camera);
  }
}

SequenceFrame SequenceTracker::Track(const GrayImage& image) {
  SequenceFrame frame;
  frame.tracked = tracker_.Track(image);
  frame.status = frame.tracked.updated ? FrameStatus::kTracked : FrameStatus::kLost;
  const PoseOfShape pose_of_shape = [this](const Vector6d& s) {
    return perspective_ ? perspective_->Pose(s, options_.form)
                        : PoseFromShape(s, options_.camera, options_.form);
  };
  try {
    frame.pose = UnscentedPose(frame.tracked.shape, frame.tracked.shape_covariance, pose_of_shape,
                               options_.form);
  } catch (const DegenerateError&) {
    frame.status = FrameStatus::kSingular;
  }
  return frame;
}

RenderedSequence RenderSequence(
    const SequenceRenderOptions& options,
    const std::function<void(const RenderedFrame&, const GrayImage&)>& on_frame) {
  RequireValid(options);
  const ClosedBSpline target(options.target);
  const ShapeSpace check(options.target);  // a collinear target has no affine deformation
  (void)check;
  RenderedSequence sequence;
  sequence.principal = Eigen::Vector2d((options.width - 1) / 2.0, (options.height - 1) / 2.0);
  RenderOptions render = options.render;
  const int frames = options.frames;
  for (int t = 0; t < frames; ++t) {
    RenderedFrame frame;
    frame.index = t;
    const double u = frames > 1 ? static_cast<double>(t) / (frames - 1) : 0.0;
    frame.motion = options.from + u * (options.to - options.from);
    const Eigen::Vector3d translation = frame.motion.head<3>();
    const Eigen::Matrix3d rotation =
        RotationZyx(frame.motion(3) / kDegreesPerRadian, frame.motion(4) / kDegreesPerRadian,
                    frame.motion(5) / kDegreesPerRadian);
    const Eigen::Matrix2Xd outline =
        PerspectiveOutline(target, rotation, translation, options.camera, sequence.principal);
    frame.outside = outline.row(0).minCoeff() < 0.0 || outline.row(1).minCoeff() < 0.0 ||
                    outline.row(0).maxCoeff() > options.width - 1.0 ||
                    outline.row(1).maxCoeff() > options.height - 1.0;
    if (frame.outside) ++sequence.outside;
    render.seed = SplitMix64(options.seed) + static_cast<std::uint64_t>(t);
    const GrayImage image = RenderPolygon(outline, options.width, options.height, render);
    frame.shape = ShapeFromPose(rotation, translation, options.camera);
    if (t == 0) {
      sequence.first_view =
          ProjectPerspective(options.target, rotation, translation, options.camera).colwise() +
          sequence.principal;
    }
    on_frame(frame, image);
    sequence.frames.push_back(frame);
  }
  return sequence;
}

}  // namespace hecal::contour
