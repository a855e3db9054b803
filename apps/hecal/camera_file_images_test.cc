// Camera files through the image commands: `hecal detect` and `hecal calibrate --images` on
// images rendered (testing/rendered_scene.h) by a camera with ViSP's one-coefficient radial
// model (plumb_bob with only k1), given as ViSP camera XML. The poses and X match the rendered
// truth and the command prints how the file was read; a camera.yaml without distortion is read
// as none, with a note.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_test_util.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <Eigen/Geometry>
#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hecal/geometry/angle_units.h"
#include "testing/csv_reader.h"
#include "testing/detection_errors.h"
#include "testing/render_once.h"
#include "testing/rendered_scene.h"
#endif

namespace hecal::cli {
namespace {

#if defined(HECAL_HAVE_OPENCV_PEERS)

using cli_test::Hecal;

constexpr int kCameraFileViews = 6;

// rendered_scene.h's RenderCamera with k1 only, the model ViSP's kud describes.
pose::CameraModel KudCamera() {
  pose::CameraModel camera = hecal::testing::RenderCamera();
  camera.distortion = {-0.12, 0.0, 0.0, 0.0, 0.0};
  return camera;
}

// The camera as vpXmlParserCamera::save writes it (both models; kdu is not used by hecal).
std::string VispXml(const pose::CameraModel& c) {
  std::ostringstream xml;
  xml << std::setprecision(17) << "<?xml version=\"1.0\"?>\n<root>\n  <camera>\n"
      << "    <name>Camera</name>\n    <image_width>" << c.width << "</image_width>\n"
      << "    <image_height>" << c.height << "</image_height>\n"
      << "    <model>\n      <type>perspectiveProjWithoutDistortion</type>\n"
      << "      <px>600</px>\n      <py>600</py>\n      <u0>320</u0>\n      <v0>240</v0>\n"
      << "    </model>\n    <model>\n      <type>perspectiveProjWithDistortion</type>\n"
      << "      <px>" << c.fx << "</px>\n      <py>" << c.fy << "</py>\n      <u0>" << c.cx
      << "</u0>\n      <v0>" << c.cy << "</v0>\n      <kud>" << c.distortion[0]
      << "</kud>\n      <kdu>0.125</kdu>\n    </model>\n  </camera>\n</root>\n";
  return xml.str();
}

// X and Z of an eye-in-hand scene (metres); the robot pose that shows view B is Z·B⁻¹·X⁻¹.
Pose TrueX() {
  return MakePose(
      Eigen::AngleAxisd(80 * kRadiansPerDegree, Eigen::Vector3d(0.3, 1.0, 0.2).normalized())
          .toRotationMatrix(),
      Eigen::Vector3d(0.05, 0.02, 0.08));
}
Pose TrueZ() {
  return MakePose(
      Eigen::AngleAxisd(160 * kRadiansPerDegree, Eigen::Vector3d::UnitX()).toRotationMatrix(),
      Eigen::Vector3d(0.5, -0.1, 0.02));
}

class CameraFileImagesTest
    : public hecal::testing::RenderOnce<CameraFileImagesTest, cli_test::CliTest> {
 public:
  static constexpr const char* kRenderFolder = "camera_file_images_test_renders";
  static void Render(const std::filesystem::path& dir) {
    hecal::testing::MakeRenderedScene(
        {.camera = KudCamera(),
         .views = hecal::testing::SpreadViews({.count = kCameraFileViews}),
         .first_seed = 200,
         .folder = dir});
  }

 protected:
  std::string Target() { return Write("target.yaml", hecal::testing::kBoardYaml); }
};

TEST_F(CameraFileImagesTest, DetectReadsVispXml) {
  const cli_test::Outcome run =
      Hecal({"detect", "--images", RenderDir().string(), "--target", Target(), "--intrinsics",
             Write("camera.xml", VispXml(KudCamera())), "--output", Path("camera.csv")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("note: " + Path("camera.xml") +
                         ": ViSP camera \"Camera\": model perspectiveProjWithDistortion, read as "
                         "plumb_bob k1 = kud = -1.2e-01"),
            std::string::npos)
      << run.out;
  const csv_test::Csv poses = csv_test::ReadCsv(Path("camera.csv"));
  const std::vector<Pose> truth = hecal::testing::SpreadViews({.count = kCameraFileViews});
  ASSERT_EQ(poses.rows.size(), truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Eigen::Quaterniond q(poses.Number(i, "qw"), poses.Number(i, "qx"), poses.Number(i, "qy"),
                               poses.Number(i, "qz"));
    const Pose T =
        MakePose(q.normalized().toRotationMatrix(),
                 Eigen::Vector3d(poses.Number(i, "x"), poses.Number(i, "y"), poses.Number(i, "z")));
    EXPECT_LT(hecal::testing::RotationErrorDeg(T, truth[i]), 0.05) << i;
    EXPECT_LT(hecal::testing::TranslationErrorMm(T, truth[i]), 0.1) << i;
  }

  // The same images with a camera.yaml that has no distortion: read as none, and said so.
  const cli_test::Outcome plain =
      Hecal({"detect", "--images", RenderDir().string(), "--target", Target(), "--intrinsics",
             Write("plain.yaml", "fx: 620\nfy: 622\ncx: 321.5\ncy: 238\n"), "--output",
             Path("plain.csv")});
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_NE(
      plain.out.find("note: " + Path("plain.yaml") + " has no distortion: read as no distortion"),
      std::string::npos)
      << plain.out;
}

TEST_F(CameraFileImagesTest, CalibrateImagesReadsVispXml) {
  std::ostringstream robot;
  robot << std::setprecision(17) << "id,x,y,z,qw,qx,qy,qz\n";
  const std::vector<Pose> views = hecal::testing::SpreadViews({.count = kCameraFileViews});
  for (int i = 0; i < kCameraFileViews; ++i) {
    const Pose G = TrueZ() * views[static_cast<size_t>(i)].inverse() * TrueX().inverse();
    const Eigen::Quaterniond q(G.linear());
    robot << "view_0" << i << "," << G.translation().x() << "," << G.translation().y() << ","
          << G.translation().z() << "," << q.w() << "," << q.x() << "," << q.y() << "," << q.z()
          << "\n";
  }
  const cli_test::Outcome run =
      Hecal({"calibrate", "--images", RenderDir().string(), "--target", Target(), "--intrinsics",
             Write("camera.xml", VispXml(KudCamera())), "--robot", Write("robot.csv", robot.str()),
             "--setup", "eye-in-hand", "--output", Path("result.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("read as plumb_bob k1 = kud"), std::string::npos) << run.out;
  const nlohmann::json result = nlohmann::json::parse(Read("result.json"));
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) M(r, c) = result["X"]["matrix"][r][c].get<double>();
  }
  EXPECT_LT(hecal::testing::RotationErrorDeg(Pose(M), TrueX()), 0.05);
  EXPECT_LT(hecal::testing::TranslationErrorMm(Pose(M), TrueX()), 0.3);
  EXPECT_EQ(result["images"]["intrinsics"]["fx"].get<double>(), 620.0);
}

#endif  // HECAL_HAVE_OPENCV_PEERS

}  // namespace
}  // namespace hecal::cli
