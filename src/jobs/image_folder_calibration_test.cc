// CalibrateFromImageFolder on rendered images (testing/rendered_scene.h) of a known eye-in-hand
// scene: a chessboard seen by a camera on a robot whose poses follow from the views and a known
// X and Z (Z = A_i X B_i, handeye/problem.h). Checks X and Z against that truth, the order in
// which the job hands out its texts (image_front_end.h: listed, intrinsics, table, the fit
// warning, then the pairing's notes), and that invalid options are refused before any text.
#include "hecal/jobs/image_folder_calibration.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "testing/camera_yaml.h"
#include "testing/detection_errors.h"
#include "testing/render_once.h"
#include "testing/rendered_scene.h"

namespace hecal::jobs {
namespace {

constexpr int kFolderViews = 8;

using hecal::testing::RigX;
using hecal::testing::RigZ;

void WriteFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// robot.csv: T_base_gripper = Z B⁻¹ X⁻¹ for the first `rows` spread views, with ids view_0<i>
// when `ids` (a row beyond kFolderViews has no image).
std::string RobotCsv(int rows, bool ids) {
  const std::vector<Pose> views = hecal::testing::SpreadViews({.count = rows});
  std::ostringstream csv;
  csv << std::setprecision(17) << (ids ? "id," : "") << "x,y,z,qw,qx,qy,qz\n";
  for (int i = 0; i < rows; ++i) {
    const Pose G = hecal::testing::RigRobotPose(views[std::size_t(i)]);
    const Eigen::Quaterniond q(G.linear());
    if (ids) csv << "view_0" << i << ",";
    csv << G.translation().x() << "," << G.translation().y() << "," << G.translation().z() << ","
        << q.w() << "," << q.x() << "," << q.y() << "," << q.z() << "\n";
  }
  return csv.str();
}

class ImageFolderCalibrationTest : public hecal::testing::RenderOnce<ImageFolderCalibrationTest> {
 public:
  static constexpr const char* kRenderFolder = "image_folder_calibration_test";
  static void Render(const std::filesystem::path& dir) {
    hecal::testing::MakeRenderedScene(
        {.views = hecal::testing::SpreadViews({.count = kFolderViews}),
         .first_seed = 100,
         .folder = dir / "images"});
    WriteFile(dir / "target.yaml", hecal::testing::kBoardYaml);
    WriteFile(dir / "camera.yaml", hecal::testing::CameraYaml(hecal::testing::RenderCamera()));
    // cx 20 px off: under the 2 px refusal, a poor fit (vision/intrinsics_fit.h).
    pose::CameraModel off = hecal::testing::RenderCamera();
    off.cx += 20.0;
    WriteFile(dir / "camera_cx_off.yaml", hecal::testing::CameraYaml(off));
    WriteFile(dir / "robot.csv", RobotCsv(kFolderViews, false));
    WriteFile(dir / "robot_ids.csv", RobotCsv(kFolderViews + 1, true));
  }

 protected:
  static ImageFolderCalibrationOptions Options(const std::string& camera,
                                               const std::string& robot) {
    ImageFolderCalibrationOptions options;
    options.images.images = (RenderDir() / "images").string();
    options.images.target = (RenderDir() / "target.yaml").string();
    options.images.intrinsics = (RenderDir() / camera).string();
    options.robot = (RenderDir() / robot).string();
    options.setup = handeye::Setup::kEyeInHand;
    return options;
  }
};

// Exact robot poses: X and Z within what sub-pixel corners allow (the CLI's test of the same
// scene measured ≤ 0.01° and ≤ 0.05 mm; asserted at 0.05° and 0.3 mm), every image used.
TEST_F(ImageFolderCalibrationTest, RecoversXAndZFromRenderedImages) {
  const ImageFolderCalibration result =
      CalibrateFromImageFolder(Options("camera.yaml", "robot.csv"), {});
  const report::ResultDocument& document = result.document;
  ASSERT_EQ(document.results.size(), 1u);
  const estimation::CalibrationResult& r = document.results.front();
  EXPECT_LT(hecal::testing::RotationErrorDeg(r.X, RigX()), 0.05);
  EXPECT_LT(hecal::testing::TranslationErrorMm(r.X, RigX()), 0.3);
  EXPECT_LT(hecal::testing::RotationErrorDeg(r.Z, RigZ()), 0.05);
  EXPECT_LT(hecal::testing::TranslationErrorMm(r.Z, RigZ()), 0.3);
  EXPECT_EQ(result.camera.fx, 620.0);
  EXPECT_EQ(result.camera.cx, 321.5);
  ASSERT_TRUE(document.images.has_value());
}

// The texts in the order the job meets them: the fit warning of the given intrinsics (set after
// the front end's last stage) before the note of the robot row that has no image.
TEST_F(ImageFolderCalibrationTest, HandsOutItsTextsInOrder) {
  std::vector<std::pair<std::string, std::string>> texts;
  JobCallbacks callbacks;
  callbacks.progress = [&](const std::string& text) { texts.emplace_back("progress", text); };
  callbacks.note = [&](const std::string& text) { texts.emplace_back("note", text); };
  callbacks.warning = [&](const std::string& text) { texts.emplace_back("warning", text); };
  ImageFolderCalibrationOptions options = Options("camera_cx_off.yaml", "robot_ids.csv");
  options.caller = "order test";
  CalibrateFromImageFolder(options, callbacks);
  ASSERT_EQ(texts.size(), 5u);
  EXPECT_EQ(texts[0].first, "progress");
  EXPECT_EQ(texts[0].second.rfind("order test: 8 image(s) in ", 0), 0u) << texts[0].second;
  EXPECT_EQ(texts[1].first, "progress");
  EXPECT_EQ(texts[1].second.rfind("intrinsics: ", 0), 0u) << texts[1].second;
  EXPECT_EQ(texts[2].first, "progress");
  EXPECT_EQ(texts[2].second.rfind("image ", 0), 0u) << texts[2].second;
  EXPECT_EQ(texts[3].first, "warning");
  EXPECT_NE(texts[3].second.find("fit the images poorly"), std::string::npos) << texts[3].second;
  EXPECT_EQ(texts[4].first, "note");
  EXPECT_NE(texts[4].second.find("id 'view_08' has no image"), std::string::npos)
      << texts[4].second;
}

// No robot table: refused naming the field, before any file is read or text handed out.
TEST_F(ImageFolderCalibrationTest, RefusesOptionsWithoutRobotTable) {
  int calls = 0;
  JobCallbacks callbacks;
  callbacks.progress = [&](const std::string&) { ++calls; };
  ImageFolderCalibrationOptions options = Options("camera.yaml", "robot.csv");
  options.robot.clear();
  try {
    CalibrateFromImageFolder(options, callbacks);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "ImageFolderCalibrationOptions.robot");
    EXPECT_NE(e.fix().find("robot pose table"), std::string::npos) << e.what();
  }
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace hecal::jobs
