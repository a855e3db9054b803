// TrackContourImages (contour_tracking.h) on a sequence of known motion rendered by
// RenderContourSequence: with the principal point the pose model is perspective and every pose
// component is within 3.5 of its own UT σ of the true motion; without it, weak perspective from
// the centroid; points on the curve become the control points they were made from (the B-spline
// knot rule, contour/bspline.h); the options name the bad field; nothing is written.
#include "hecal/jobs/contour_tracking.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/perspective_view.h"
#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/io/atomic_file.h"
#include "hecal/jobs/contour_rendering.h"
#include "testing/options_validity.h"
#include "testing/thrown.h"

namespace hecal::jobs {
namespace {

namespace fs = std::filesystem;

// The built-in target (≈ 250 × 180 mm) at 5 m with f = 3000 px in a 320 × 240 image, 10 frames
// approaching 500 mm, moving (30, −20) mm and turning to Rx 15°, Ry 10°, Rz 20°; rendered once
// for every test.
class ContourTrackingTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    folder_ = new fs::path(fs::temp_directory_path() /
                           ("hecal_contour_tracking_" + std::to_string(::getpid())));
    ContourRenderingOptions options;
    options.sequence.camera = {3000.0, 5000.0};
    options.sequence.frames = 10;
    options.sequence.to << 30, -20, -500, 15, 10, 20;
    options.sequence.width = 320;
    options.sequence.height = 240;
    options.sequence.render.noise_sigma = 3.0;
    options.sequence.render.quantize = true;
    io::StagedFolder staged("", folder_->string());
    rendering_ = new ContourRendering(RenderContourSequence(
        options,
        [&](const std::string& name, const std::string& png) { staged.Stage(name, png); }));
    staged.Stage("init.csv", rendering_->init_csv);
    staged.Commit();
  }
  static void TearDownTestSuite() {
    fs::remove_all(*folder_);
    delete folder_;
    delete rendering_;
  }

  static ContourTrackingOptions Options() {
    ContourTrackingOptions options;
    options.images = folder_->string();
    options.init = (*folder_ / "init.csv").string();
    options.tracking.camera = {3000.0, 5000.0};
    return options;
  }

  static fs::path* folder_;
  static ContourRendering* rendering_;
};
fs::path* ContourTrackingTest::folder_ = nullptr;
ContourRendering* ContourTrackingTest::rendering_ = nullptr;

TEST_F(ContourTrackingTest, WithThePrincipalPointThePoseIsWithinItsSigmaOfTheTruth) {
  ContourTrackingOptions options = Options();
  options.principal = Eigen::Vector2d(159.5, 119.5);  // the render's image centre
  std::vector<std::string> progress;
  JobCallbacks callbacks;
  callbacks.progress = [&](const std::string& text) { progress.push_back(text); };
  std::vector<std::string> seen;
  const report::ContourTrack track = TrackContourImages(
      options, callbacks, [&](const contour::TrackedImage& image) { seen.push_back(image.image); });
  ASSERT_EQ(progress.size(), 1u);
  EXPECT_EQ(progress[0],
            "pose model: perspective (weak-perspective bias removed, principal point given)\n");
  EXPECT_TRUE(track.options.perspective);
  EXPECT_EQ(track.options.principal, Eigen::Vector2d(159.5, 119.5));
  ASSERT_EQ(track.frames.size(), 10u);
  ASSERT_EQ(seen.size(), 10u);
  for (std::size_t t = 0; t < 10; ++t) {
    const contour::RenderedFrame& truth = rendering_->rendered.frames[t];
    EXPECT_EQ(seen[t], "frame_000" + std::to_string(t) + ".png");
    EXPECT_EQ(track.frames[t].image, seen[t]);
    ASSERT_EQ(track.frames[t].frame.status, contour::FrameStatus::kTracked) << t;
    if (t == 0) continue;  // the template view
    const Eigen::Matrix3d R = contour::RotationZyx(truth.motion(3) * kRadiansPerDegree,
                                                   truth.motion(4) * kRadiansPerDegree,
                                                   truth.motion(5) * kRadiansPerDegree);
    const Vector6d expected = contour::PoseParameters(
        contour::CanonicalPose(R, truth.motion.head<3>(), contour::RotationForm::kZyx));
    const contour::ContourPoseUncertainty& pose = *track.frames[t].frame.pose;
    for (int j = 0; j < 6; ++j) {
      // Rx, Ry and Tz (correlated with them) only from 10° of tilt on: below, the tilt's sign
      // fold biases all three (docs/contour.md#the-bias-check).
      if (j >= 2 && j <= 4 && std::acos(R(2, 2)) < 10.0 * kRadiansPerDegree) continue;
      EXPECT_NEAR(pose.parameters(j), expected(j), 3.5 * std::sqrt(pose.covariance(j, j)))
          << "frame " << t << " parameter " << j;
    }
  }
}

TEST_F(ContourTrackingTest, WithoutItWeakPerspectiveFromTheCentroidOfCurvePoints) {
  // Points on the curve at the knots, r(i) = (Q_{i−1} + 4 Q_i + Q_{i+1}) / 6, of the rendered
  // first view's control points Q: the job must recover Q.
  const Eigen::Matrix2Xd& Q = rendering_->rendered.first_view;
  const Eigen::Index n = Q.cols();
  std::ofstream curve(*folder_ / "curve.txt");
  curve.precision(17);
  curve << "x y\n";
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector2d r = (Q.col((i + n - 1) % n) + 4 * Q.col(i) + Q.col((i + 1) % n)) / 6;
    curve << r.x() << " " << r.y() << "\n";
  }
  curve.close();
  ContourTrackingOptions options = Options();
  options.init = (*folder_ / "curve.txt").string();
  options.init_on_curve = true;
  std::string progress;
  JobCallbacks callbacks;
  callbacks.progress = [&](const std::string& text) { progress += text; };
  const report::ContourTrack track = TrackContourImages(options, callbacks);
  EXPECT_EQ(progress,
            "pose model: weak perspective (the contour paper's; give --principal-point for "
            "perspective)\n");
  EXPECT_FALSE(track.options.perspective);
  ASSERT_EQ(track.options.control.cols(), n);
  EXPECT_LT((track.options.control - Q).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((track.options.principal - Q.rowwise().mean()).norm(), 1e-9);
  ASSERT_EQ(track.frames.size(), 10u);
  EXPECT_EQ(track.frames[9].frame.status, contour::FrameStatus::kTracked);
  // The pose model can be chosen against the default.
  options.perspective = true;
  EXPECT_TRUE(TrackContourImages(options, {}).options.perspective);
  fs::remove(*folder_ / "curve.txt");
}

TEST(ContourTrackingOptionsTest, IsValidNamesTheField) {
  ContourTrackingOptions options;
  options.images = "frames";
  options.init = "init.csv";
  EXPECT_TRUE(testing::IsValidOptions(options));
  EXPECT_TRUE(testing::RefusesNaming(options, "ContourTrackingOptions.images",
                                     [](ContourTrackingOptions& o) { o.images.clear(); }));
  EXPECT_TRUE(testing::RefusesNaming(options, "ContourTrackingOptions.init",
                                     [](ContourTrackingOptions& o) { o.init.clear(); }));
  EXPECT_TRUE(testing::RefusesNaming(options, "ContourCamera.focal", [](ContourTrackingOptions& o) {
    o.tracking.camera.focal = 0;
  }));
  EXPECT_TRUE(testing::RefusesNaming(
      options, "EdgeSearchOptions.range",
      [](ContourTrackingOptions& o) { o.tracking.tracker.search.range = 1; }));
  // Checked before any file is read: the missing files are never reached.
  options.tracking.camera.z0 = -1;
  EXPECT_EQ(testing::Thrown<InputError>([&] { TrackContourImages(options, {}); }).source(),
            "ContourCamera.z0");
}

}  // namespace
}  // namespace hecal::jobs
