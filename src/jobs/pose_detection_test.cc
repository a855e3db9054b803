// DetectCameraPoses on rendered images (testing/rendered_scene.h) of a 9 × 6 chessboard seen from
// known views: the pose table holds each view's T_camera_target, the points every corner of every
// image by id, with the intrinsics given and estimated from the images; invalid options are
// refused before any text.
#include "hecal/jobs/pose_detection.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hecal/core/error.h"
#include "testing/camera_yaml.h"
#include "testing/detection_errors.h"
#include "testing/render_once.h"
#include "testing/rendered_scene.h"
#include "testing/thrown.h"

namespace hecal::jobs {
namespace {

using ::testing::HasSubstr;

constexpr int kDetectionViews = 6;
constexpr int kCorners = 9 * 6;

class PoseDetectionTest : public hecal::testing::RenderOnce<PoseDetectionTest> {
 public:
  static constexpr const char* kRenderFolder = "pose_detection_test";
  static void Render(const std::filesystem::path& dir) {
    hecal::testing::MakeRenderedScene(
        {.views = hecal::testing::SpreadViews({.count = kDetectionViews}),
         .first_seed = 300,
         .folder = dir / "images"});
    std::ofstream(dir / "target.yaml") << hecal::testing::kBoardYaml;
    std::ofstream(dir / "camera.yaml")
        << hecal::testing::CameraYaml(hecal::testing::RenderCamera());
  }

 protected:
  static PoseDetectionOptions Options(const std::string& camera) {
    PoseDetectionOptions options;
    options.images.images = (RenderDir() / "images").string();
    options.images.target = (RenderDir() / "target.yaml").string();
    options.images.intrinsics = camera.empty() ? "" : (RenderDir() / camera).string();
    options.images.threads = 1;
    options.output = (RenderDir() / "det.csv").string();
    return options;
  }

  // Every view in the table, in order, at its known pose; every corner of every view in the
  // points, image by image in id order.
  static void ExpectTheViews(const PoseDetection& result, double max_deg, double max_mm) {
    const std::vector<Pose> views = hecal::testing::SpreadViews({.count = kDetectionViews});
    ASSERT_EQ(result.table.rows.size(), std::size_t(kDetectionViews));
    ASSERT_EQ(result.points.size(), std::size_t(kDetectionViews * kCorners));
    for (int i = 0; i < kDetectionViews; ++i) {
      const io::PoseRow& row = result.table.rows[std::size_t(i)];
      EXPECT_EQ(row.id, "view_0" + std::to_string(i));
      EXPECT_LT(hecal::testing::RotationErrorDeg(row.pose, views[std::size_t(i)]), max_deg) << i;
      EXPECT_LT(hecal::testing::TranslationErrorMm(row.pose, views[std::size_t(i)]), max_mm) << i;
      for (int k = 0; k < kCorners; ++k) {
        const io::DetectedPoint& point = result.points[std::size_t(i * kCorners + k)];
        EXPECT_EQ(point.image, row.id);
        EXPECT_EQ(point.point_id, k);
      }
    }
    EXPECT_EQ(result.table.source, (RenderDir() / "det.csv").string());
  }
};

// Given intrinsics: the poses within what sub-pixel corners allow (measured ≤ 0.01° and
// ≤ 0.02 mm; asserted at 0.05° and 0.1 mm), no camera.yaml.
TEST_F(PoseDetectionTest, GivenIntrinsicsRecoverTheViews) {
  const PoseDetection result = DetectCameraPoses(Options("camera.yaml"), {});
  ExpectTheViews(result, 0.05, 0.1);
  EXPECT_FALSE(result.camera_yaml.has_value());
  EXPECT_EQ(result.camera.fx, hecal::testing::RenderCamera().fx);
  ASSERT_EQ(result.write.comments.size(), 3u);
  EXPECT_EQ(result.write.comments[2], "intrinsics: " + (RenderDir() / "camera.yaml").string());
}

// Estimated intrinsics: near the rendering camera, written as camera.yaml beside det.csv with the
// images and the RMS in its '#' lines; the poses still near the views (measured ≤ 0.012° and
// ≤ 0.12 mm; asserted at 0.05° and 0.5 mm).
TEST_F(PoseDetectionTest, EstimatedIntrinsicsAreReturnedAsCameraYaml) {
  PoseDetectionOptions options = Options("");
  options.caller = "detection test";
  const PoseDetection result = DetectCameraPoses(options, {});
  ExpectTheViews(result, 0.05, 0.5);
  const pose::CameraModel truth = hecal::testing::RenderCamera();
  EXPECT_NEAR(result.camera.fx, truth.fx, 0.02 * truth.fx);
  EXPECT_NEAR(result.camera.cx, truth.cx, 10.0);
  ASSERT_TRUE(result.camera_yaml.has_value());
  EXPECT_THAT(*result.camera_yaml,
              HasSubstr("# estimated by detection test (cv::calibrateCamera) from 6 images in " +
                        options.images.images + ", 640x480\n"));
  EXPECT_THAT(*result.camera_yaml, HasSubstr("# RMS reprojection error "));
  EXPECT_EQ(result.write.comments[0].rfind("detection test: T_camera_target of each image", 0), 0u);
  EXPECT_EQ(result.write.comments[2],
            "intrinsics: estimated from the images, " + (RenderDir() / "det.camera.yaml").string());
}

// No output path: refused naming the field, before any file is read or text handed out.
TEST_F(PoseDetectionTest, RefusesOptionsWithoutOutput) {
  int calls = 0;
  JobCallbacks callbacks;
  callbacks.progress = [&](const std::string&) { ++calls; };
  PoseDetectionOptions options = Options("camera.yaml");
  options.output.clear();
  const InputError error =
      hecal::testing::Thrown<InputError>([&] { DetectCameraPoses(options, callbacks); });
  EXPECT_EQ(error.source(), "PoseDetectionOptions.output");
  options.images.threads = -1;
  EXPECT_EQ(
      hecal::testing::Thrown<InputError>([&] { DetectCameraPoses(options, callbacks); }).source(),
      "ImageSetOptions.threads");
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace hecal::jobs
