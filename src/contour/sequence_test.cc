// RenderSequence and SequenceTracker (sequence.h) in memory: the rendered motion is the linear
// interpolation asked for, frames leaving the image are counted, and tracking the rendered
// frames recovers the shape vectors of the known motion (the truth the renderer was given, not
// its output).
#include "hecal/contour/sequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "hecal/contour/contour_study.h"
#include "hecal/core/error.h"

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

// IsValid names the field that is out of its range, and only that one.
void ExpectInvalid(const SequenceRenderOptions& options, const std::string& field) {
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_EQ(why.rfind(field + ": ", 0), 0u) << why;
}

TEST(SequenceRenderOptionsTest, IsValidNamesTheFieldOutOfRange) {
  const SequenceRenderOptions good = Options(6, Vector6d::Zero());
  std::string why;
  EXPECT_TRUE(good.IsValid(&why)) << why;
  const auto with = [&](auto change) {
    SequenceRenderOptions options = good;
    change(options);
    return options;
  };
  ExpectInvalid(with([](auto& o) { o.camera.focal = 0.0; }), "ContourCamera.focal");
  ExpectInvalid(with([](auto& o) { o.camera.z0 = -1.0; }), "ContourCamera.z0");
  ExpectInvalid(with([](auto& o) { o.frames = 0; }), "SequenceRenderOptions.frames");
  ExpectInvalid(with([](auto& o) { o.frames = 10001; }), "SequenceRenderOptions.frames");
  EXPECT_TRUE(with([](auto& o) { o.frames = 10000; }).IsValid(nullptr));
  ExpectInvalid(with([](auto& o) { o.width = 7; }), "SequenceRenderOptions.size");
  ExpectInvalid(with([](auto& o) { o.height = 20001; }), "SequenceRenderOptions.size");
  EXPECT_TRUE(with([](auto& o) { o.width = o.height = 8; }).IsValid(nullptr));
  // 20000 × 5001 px is above 10^8 pixels a frame; 10000 frames of 500 × 500 above 2·10^9.
  ExpectInvalid(with([](auto& o) { o.width = 20000, o.height = 5001, o.frames = 1; }),
                "SequenceRenderOptions.size");
  EXPECT_TRUE(
      with([](auto& o) { o.width = 20000, o.height = 5000, o.frames = 1; }).IsValid(nullptr));
  ExpectInvalid(with([](auto& o) { o.width = 500, o.height = 500, o.frames = 10000; }),
                "SequenceRenderOptions.size");
  ExpectInvalid(with([](auto& o) { o.render.noise_sigma = 256.0; }), "RenderOptions.noise_sigma");
  ExpectInvalid(with([](auto& o) { o.render.noise_sigma = std::nan(""); }),
                "RenderOptions.noise_sigma");
  ExpectInvalid(with([](auto& o) { o.render.blur_sigma = -0.1; }), "RenderOptions.blur_sigma");
  ExpectInvalid(with([](auto& o) { o.target = o.target.leftCols(3).eval(); }),
                "SequenceRenderOptions.target");
  // RenderSequence refuses what IsValid refuses, before any frame.
  int rendered = 0;
  EXPECT_THROW(RenderSequence(with([](auto& o) { o.frames = 0; }),
                              [&](const RenderedFrame&, const GrayImage&) { ++rendered; }),
               InputError);
  EXPECT_EQ(rendered, 0);
}

TEST(SequenceTrackingOptionsTest, IsValidNamesTheFieldOutOfRange) {
  SequenceTrackingOptions good;
  good.camera = {3000.0, 5000.0};
  std::string why;
  EXPECT_TRUE(good.IsValid(&why)) << why;
  SequenceTrackingOptions o = good;
  o.camera.focal = std::nan("");
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_EQ(why.rfind("ContourCamera.focal: ", 0), 0u) << why;
  for (const double range : {1.9, 200.1}) {
    o = good;
    o.tracker.search.range = range;
    EXPECT_FALSE(o.IsValid(&why)) << range;
    EXPECT_EQ(why.rfind("EdgeSearchOptions.range: ", 0), 0u) << why;
  }
  o.tracker.search.range = 200.0;
  EXPECT_TRUE(o.IsValid(nullptr));
  for (const double sigma : {0.0, 100.5}) {
    o = good;
    o.tracker.measurement_sigma = sigma;
    EXPECT_FALSE(o.IsValid(&why)) << sigma;
    EXPECT_EQ(why.rfind("ShapeTrackerOptions.measurement_sigma: ", 0), 0u) << why;
  }
  o.tracker.measurement_sigma = 100.0;
  EXPECT_TRUE(o.IsValid(nullptr));
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
