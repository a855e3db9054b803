// The image front end's texts (image_set_text.h) on image sets built by hand, against lines
// written out by hand: the listed line for image files and for station sub-folders, given and
// estimated intrinsics, and the per-image table with a used and a skipped image.
#include "hecal/jobs/image_set_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "testing/rendered_scene.h"

namespace hecal::jobs {
namespace {

vision::ImageRecord Used(const std::string& name) {
  vision::ImageRecord image;
  image.name = name;
  image.detection.status = vision::DetectionStatus::kFound;
  image.detection.points.resize(54);
  image.detection.total_points = 54;
  image.detection.sharpness = 2.5;
  pose::RefinementResult pose;
  pose.rms_px = 0.123;
  // 1σ 0.01° on every rotation axis, 5 mm on every translation axis.
  const double sigma_rad = 0.01 * std::numbers::pi / 180.0;
  pose.covariance = Matrix6d::Zero();
  pose.covariance.diagonal() << sigma_rad * sigma_rad, sigma_rad * sigma_rad, sigma_rad * sigma_rad,
      25e-6, 25e-6, 25e-6;
  image.pose = pose;
  return image;
}

vision::ImageSet TwoImages() {
  vision::ImageSet set;
  set.target = testing::Board();
  set.board = pose::ObjectPoints(set.target);
  set.images = {Used("im_01.png"), Used("im_02.png")};
  set.camera = testing::RenderCamera();
  return set;
}

TEST(ImageSetText, ListedLineNamesTheCallerFolderAndTarget) {
  vision::ImageSet set = TwoImages();
  vision::ImageSetOptions options;
  options.images = "shots";
  EXPECT_EQ(ImageSetListedText(set, options, "hecal detect"),
            "hecal detect: 2 image(s) in shots, target chessboard 9x6 (54 points)\n");
  set.sub_folders = true;
  EXPECT_EQ(ImageSetListedText(set, options, "run"),
            "run: 2 station sub-folder(s) in shots, target chessboard 9x6 (54 points)\n");
}

TEST(ImageSetText, GivenIntrinsicsWithTheCameraFilesNotes) {
  vision::ImageSet set = TwoImages();
  set.camera_notes = {"no distortion given"};
  vision::ImageSetOptions options;
  options.intrinsics = "camera.yaml";
  EXPECT_EQ(ImageSetIntrinsicsText(set, options),
            "intrinsics: camera.yaml (fx 620, fy 622, cx 321.5, cy 238 px)\n"
            "note: no distortion given\n");
}

// The estimate's warnings are the caller's to hand out: not in the text.
TEST(ImageSetText, EstimatedIntrinsicsWithTheirSigma) {
  vision::ImageSet set = TwoImages();
  vision::IntrinsicsResult estimated;
  estimated.camera = {1056.29312,
                      1056.4551,
                      958.7841,
                      586.8559,
                      1920,
                      1200,
                      {-0.1318174, 0.1012893, 0.0001431, 0.0002879, -0.0521024}};
  estimated.rms_px = 0.07912;
  estimated.coverage = 0.564;
  estimated.normal_spread_deg = 45.18;
  estimated.sigma = {0.0691, 0.0684, 0.0521, 0.0403, {0.00023, 0.001264, 8e-6, 1e-5, 0.002037}};
  estimated.warnings = {"only 2 views"};
  set.estimated = estimated;
  EXPECT_EQ(ImageSetIntrinsicsText(set, {}),
            "intrinsics: estimated from 2 images (cv::calibrateCamera), RMS 0.0791 px; the points "
            "cover 56% of the image, board normals spread over 45.2 deg\n"
            "  fx 1056.293 ± 0.069  fy 1056.455 ± 0.068  cx 958.784 ± 0.052  cy 586.856 ± 0.040 "
            "px (1 sigma)\n"
            "  k1 -0.131817 ± 0.000230  k2 0.101289 ± 0.001264  p1 0.000143 ± 0.000008  p2 "
            "0.000288 ± 0.000010  k3 -0.052102 ± 0.002037\n");
}

// The first column widens to the longest name; a skipped image gives its reason after the
// sharpness.
TEST(ImageSetText, TableRowPerImage) {
  vision::ImageRecord skipped;
  skipped.name = "pose_10/image.png";
  skipped.detection.status = vision::DetectionStatus::kNotFound;
  skipped.detection.total_points = 54;
  skipped.detection.sharpness = 3.0;
  skipped.skipped = "target not found";
  EXPECT_EQ(ImageTableText({Used("im_01.png"), skipped}),
            "image              status     points     sharp_px  rms_px   sigma_mm  sigma_deg\n"
            "im_01.png          found      54/54      2.50      0.123    5.000     0.0100\n"
            "pose_10/image.png  not_found  0/54       3.00      skipped: target not found\n");
}

}  // namespace
}  // namespace hecal::jobs
