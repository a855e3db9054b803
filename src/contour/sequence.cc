// Tracking and rendering contour sequences: see sequence.h.
#include "hecal/contour/sequence.h"

#include <numbers>

#include "hecal/contour/bspline.h"
#include "hecal/contour/perspective_view.h"
#include "hecal/contour/shape_space.h"
#include "hecal/core/error.h"
#include "hecal/core/split_mix.h"

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

SequenceTracker::SequenceTracker(const SequenceTrackingOptions& options)
    : options_(options), tracker_(options.control, options.principal, options.tracker) {
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
  constexpr double kDegrees = 180.0 / std::numbers::pi;  // as the motion is given
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
    const Eigen::Matrix3d rotation = RotationZyx(
        frame.motion(3) / kDegrees, frame.motion(4) / kDegrees, frame.motion(5) / kDegrees);
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
