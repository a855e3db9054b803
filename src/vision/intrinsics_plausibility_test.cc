// CheckIntrinsicsPlausible: intrinsics estimated from correctly described views pass (rendered
// truth, and 6 real images of data/rwhe-kuka2 with its 24 × 17 board); views whose pixels are
// paired with the wrong grid points in half the images (each row read one corner late, as when
// the grid's layout differs from the description; a mirrored or transposed order would not do:
// that is a rigid turn of a planar board) are refused on their RMS; each physical test refuses the
// camera that breaks it alone (the figures of the 9 × 6-of-24 × 17 misdescription among them),
// and the fold radius matches its closed form.
#include "hecal/vision/intrinsics_plausibility.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "testing/kuka2_views.h"
#include "testing/options_validity.h"
#include "testing/rendered_scene.h"

namespace hecal::vision {
namespace {

bool Mentions(const IntrinsicsPlausibility& result, const std::string& text) {
  for (const std::string& problem : result.problems) {
    if (problem.find(text) != std::string::npos) return true;
  }
  return false;
}

// Views of the rendered scene's 9 × 6 board through the detection camera; with `misread`, the
// odd views pair every pixel with the next grid point in row-major order (the last wraps round).
std::vector<CalibrationView> RenderedViews(bool misread) {
  const pose::TargetSpec board = hecal::testing::Board();
  const std::vector<Pose> poses = hecal::testing::SpreadViews({.count = 8});
  std::vector<CalibrationView> views;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const hecal::testing::StationImage truth =
        hecal::testing::ProjectedTruth(board, hecal::testing::DetectionCamera(), poses[k]);
    CalibrationView view{truth.target, truth.pixels};
    if (misread && k % 2 == 1) {
      std::rotate(view.object_points.begin(), view.object_points.begin() + 1,
                  view.object_points.end());
    }
    views.push_back(view);
  }
  return views;
}

IntrinsicsResult Estimate(const pose::CameraModel& camera, double rms_px) {
  IntrinsicsResult result;
  result.camera = camera;
  result.rms_px = rms_px;
  return result;
}

TEST(IntrinsicsPlausibility, CorrectlyDescribedRenderedViewsPass) {
  const IntrinsicsResult estimate = CalibrateIntrinsics(RenderedViews(false), 800, 600);
  const IntrinsicsPlausibility result = CheckIntrinsicsPlausible(estimate);
  EXPECT_TRUE(result.plausible()) << (result.problems.empty() ? "" : result.problems.front());
}

TEST(IntrinsicsPlausibility, MisreadGridIsRefusedOnItsRms) {
  const IntrinsicsResult estimate = CalibrateIntrinsics(RenderedViews(true), 800, 600);
  const IntrinsicsPlausibility result = CheckIntrinsicsPlausible(estimate);
  EXPECT_FALSE(result.plausible());
  EXPECT_TRUE(Mentions(result, "reprojection RMS")) << estimate.rms_px;
}

TEST(IntrinsicsPlausibility, RealKuka2EstimatePasses) {
  const kuka2::Views loaded = kuka2::Load({1, 5, 10, 15, 20, 25});
  const std::vector<pose::ObjectPoint> board = pose::ObjectPoints(kuka2::Target());
  std::vector<CalibrationView> views;
  for (const Detection& detection : loaded.detections) {
    ASSERT_TRUE(detection.usable()) << detection.message;
    CalibrationView view;
    for (const ImagePoint& p : detection.points) {
      view.object_points.push_back(board[static_cast<std::size_t>(p.id)].position);
      view.image_points.push_back(p.pixel);
    }
    views.push_back(view);
  }
  const IntrinsicsResult estimate = CalibrateIntrinsics(views, 1920, 1200);
  const IntrinsicsPlausibility result = CheckIntrinsicsPlausible(estimate);
  EXPECT_TRUE(result.plausible()) << (result.problems.empty() ? "" : result.problems.front());
  // Against the reference camera: the check passes a real camera, not merely this estimate.
  EXPECT_TRUE(CheckIntrinsicsPlausible(Estimate(kuka2::Camera(), 0.074)).plausible());
}

TEST(IntrinsicsPlausibility, EachTestRefusesTheCameraThatBreaksIt) {
  const pose::CameraModel good = kuka2::Camera();
  EXPECT_TRUE(CheckIntrinsicsPlausible(Estimate(good, 1.9)).plausible());
  EXPECT_TRUE(Mentions(CheckIntrinsicsPlausible(Estimate(good, 2.0)), "reprojection RMS 2.00"));

  pose::CameraModel stretched = good;
  stretched.fy = 1.49 * good.fx;
  EXPECT_TRUE(CheckIntrinsicsPlausible(Estimate(stretched, 0.1)).plausible());
  stretched.fx = 5045.0;  // the 9 × 6-of-24 × 17 estimate
  stretched.fy = 40971.0;
  const IntrinsicsPlausibility ratio = CheckIntrinsicsPlausible(Estimate(stretched, 0.1));
  ASSERT_EQ(ratio.problems.size(), 1u);
  EXPECT_TRUE(Mentions(ratio, "factor 8.12"));

  pose::CameraModel folded = good;
  folded.distortion = {0.0, -1622.0, 0.0, 0.0, 0.0};
  const IntrinsicsPlausibility fold = CheckIntrinsicsPlausible(Estimate(folded, 0.1));
  ASSERT_EQ(fold.problems.size(), 1u);
  EXPECT_TRUE(Mentions(fold, "folds the image"));

  pose::CameraModel shifted = good;
  shifted.distortion = {};  // kuka2's lens folds at radius 1.32, reached with cx this far off
  shifted.cx = 0.5 * 1919 + 0.24 * 1920;
  EXPECT_TRUE(CheckIntrinsicsPlausible(Estimate(shifted, 0.1)).plausible());
  shifted.cx = 0.5 * 1919 + 0.26 * 1920;
  EXPECT_TRUE(Mentions(CheckIntrinsicsPlausible(Estimate(shifted, 0.1)), "principal point"));
}

// slope 1 + 3 k1 r² = 0 at r = √(−1 / (3 k1)); beyond r_max it is not reported.
TEST(IntrinsicsPlausibility, FoldRadiusMatchesTheClosedForm) {
  pose::CameraModel camera = kuka2::Camera();
  camera.distortion = {-0.5, 0.0, 0.0, 0.0, 0.0};
  const double fold = std::sqrt(2.0 / 3.0);
  EXPECT_NEAR(RadialFoldRadius(camera, 1.0), fold, 1e-3);
  EXPECT_LT(RadialFoldRadius(camera, 0.8), 0.0);
  camera.distortion = kuka2::Camera().distortion;
  EXPECT_LT(RadialFoldRadius(camera, 1.3), 0.0);  // corner radius 1.07; folds at 1.32
}

TEST(IntrinsicsPlausibilityOptions, IsValidNamesTheField) {
  using hecal::testing::RefusesNaming;
  const IntrinsicsPlausibilityOptions defaults;
  EXPECT_TRUE(hecal::testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsPlausibilityOptions.max_rms_px",
                            [](auto& o) { o.max_rms_px = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsPlausibilityOptions.max_principal_offset",
                            [](auto& o) { o.max_principal_offset = NAN; }));
  EXPECT_TRUE(RefusesNaming(defaults, "IntrinsicsPlausibilityOptions.max_focal_ratio",
                            [](auto& o) { o.max_focal_ratio = 1.0; }));
}

}  // namespace
}  // namespace hecal::vision
