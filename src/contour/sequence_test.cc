// RenderSequence and SequenceTracker (sequence.h) in memory: the rendered motion is the linear
// interpolation asked for, frames leaving the image are counted, and tracking the rendered
// frames recovers the shape vectors of the known motion (the truth the renderer was given, not
// its output).
#include "hecal/contour/sequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hecal/contour/contour_study.h"

namespace hecal::contour {
namespace {

// The built-in target at 5 m, f = 3000 px, in a 320 × 240 image (≈ 150 × 110 px).
SequenceRenderOptions Options(int frames, const Vector6d& to) {
  SequenceRenderOptions options;
  options.target = DefaultTarget();
  options.camera = {3000.0, 5000.0};
  options.frames = frames;
  options.to = to;
  options.width = 320;
  options.height = 240;
  options.render.noise_sigma = 3.0;
  options.render.quantize = true;
  return options;
}

TEST(RenderSequenceTest, InterpolatesTheMotionLinearly) {
  const Vector6d to = (Vector6d() << 40, -20, -400, 8, 4, 12).finished();
  int calls = 0;
  const RenderedSequence sequence =
      RenderSequence(Options(5, to), [&](const RenderedFrame& frame, const GrayImage& image) {
        EXPECT_EQ(frame.index, calls++);
        EXPECT_EQ(image.width(), 320);
        EXPECT_EQ(image.height(), 240);
      });
  ASSERT_EQ(calls, 5);
  ASSERT_EQ(sequence.frames.size(), 5u);
  EXPECT_EQ(sequence.principal, Eigen::Vector2d(159.5, 119.5));
  EXPECT_TRUE(sequence.frames[0].motion.isZero());
  const Vector6d middle = (Vector6d() << 20, -10, -200, 4, 2, 6).finished();
  EXPECT_TRUE(sequence.frames[2].motion.isApprox(middle, 1e-14));
  EXPECT_TRUE(sequence.frames[4].motion.isApprox(to, 1e-14));
  EXPECT_EQ(sequence.outside, 0);
  // The first view is fronto-parallel at Z0: the target scaled by f / Z0 about the centre.
  const Eigen::Matrix2Xd expected =
      (DefaultTarget() * (3000.0 / 5000.0)).colwise() + sequence.principal;
  EXPECT_TRUE(sequence.first_view.isApprox(expected, 1e-12));
  // Its S is zero: no motion, no deformation.
  EXPECT_LT(sequence.frames[0].shape.norm(), 1e-12);
}

TEST(RenderSequenceTest, CountsFramesWhereTheTargetLeavesTheImage) {
  // Tx = 600 mm at 5 m is 360 px: the target leaves the 320 px image from about the middle on.
  const RenderedSequence sequence =
      RenderSequence(Options(5, (Vector6d() << 600, 0, 0, 0, 0, 0).finished()),
                     [](const RenderedFrame&, const GrayImage&) {});
  EXPECT_GE(sequence.outside, 2);
  EXPECT_LE(sequence.outside, 3);
  EXPECT_FALSE(sequence.frames[0].outside);
  EXPECT_TRUE(sequence.frames[4].outside);
}

TEST(SequenceTrackerTest, TracksARenderedSequenceToItsShapeVectors) {
  const Vector6d to = (Vector6d() << 6, -4, -100, 3, 2, 4).finished();
  std::vector<GrayImage> images;
  const RenderedSequence sequence = RenderSequence(
      Options(6, to),
      [&](const RenderedFrame&, const GrayImage& image) { images.push_back(image); });
  SequenceTrackingOptions options;
  options.control = sequence.first_view;
  options.principal = sequence.first_view.rowwise().mean();
  options.camera = {3000.0, 5000.0};
  SequenceTracker tracker(options);
  for (std::size_t t = 0; t < images.size(); ++t) {
    const SequenceFrame frame = tracker.Track(images[t]);
    EXPECT_EQ(FrameStatusName(frame.status), "tracked") << t;
    ASSERT_TRUE(frame.pose.has_value()) << t;
    const Vector6d& truth = sequence.frames[t].shape;
    for (int i = 0; i < 6; ++i) {
      const double sd = std::sqrt(frame.tracked.shape_covariance(i, i));
      EXPECT_NEAR(frame.tracked.shape(i), truth(i), 4 * sd + (i < 2 ? 0.5 : 1e-3)) << t << " " << i;
    }
    // Tz of the weak-perspective pose against the rendered approach (mm).
    EXPECT_NEAR(frame.pose->parameters(2), sequence.frames[t].motion(2), 15.0) << t;
  }
}

}  // namespace
}  // namespace hecal::contour
