// `hecal pose` end to end: synthetic points with a known pose written as files, the command run
// in-process, the printed summary and the JSON checked against the truth; pairing by id and by
// order, units, the camera flags, the methods (and the OpenCV ones when built with vision), and
// bad input (exit 2, file:line, nothing written).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "cli.h"
#include "cli_test_util.h"
#include "testing/camera_yaml.h"
#include "testing/pose_scenes.h"

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;
using nlohmann::json;

using ::hecal::testing::CameraYaml;

// object.csv with ids p0.. in millimetres; image.csv with the ids of `image_order` (a subset of
// the points, in that order).
std::string ObjectCsvMm(const testing::PointView& scene) {
  std::ostringstream csv;
  csv << std::setprecision(17) << "# a target with known points\nid,x_mm,y_mm,z_mm\n";
  for (std::size_t k = 0; k < scene.object_points.size(); ++k) {
    const Eigen::Vector3d P = 1000.0 * scene.object_points[k];
    csv << 'p' << k << ',' << P.x() << ',' << P.y() << ',' << P.z() << '\n';
  }
  return csv.str();
}

std::string ImageCsv(const testing::PointView& scene, const std::vector<std::size_t>& order,
                     bool ids) {
  std::ostringstream csv;
  csv << std::setprecision(17) << (ids ? "id,u,v\n" : "u,v\n");
  for (std::size_t k : order) {
    if (ids) csv << 'p' << k << ',';
    csv << scene.pixels[k].x() << ',' << scene.pixels[k].y() << '\n';
  }
  return csv.str();
}

Pose PoseOf(const json& object, double metres_per_unit) {
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) M(r, c) = object["matrix"][r][c].get<double>();
  }
  Pose T(M);
  T.translation() *= metres_per_unit;
  return T;
}

double RotationError(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

class PoseCommand : public CliTest {
 protected:
  testing::PointView Scene(int points, testing::PointShape shape, uint64_t seed) {
    std::mt19937_64 rng(seed);
    return testing::RandomScene(rng, points, shape);
  }
};

TEST_F(PoseCommand, LinearWithIntrinsicsPairsByIdAndWritesTheResult) {
  const testing::PointView scene = Scene(14, testing::PointShape::kVolume, 1);
  Write("object.csv", ObjectCsvMm(scene));
  // Image points in another order, two object points not seen.
  Write("image.csv", ImageCsv(scene, {5, 2, 11, 0, 7, 1, 9, 3, 12, 6, 10, 4}, true));
  Write("camera.yaml", CameraYaml(scene.camera));
  const cli_test::Outcome run =
      Hecal({"pose", "--points", Path("object.csv"), "--image-points", Path("image.csv"),
             "--intrinsics", Path("camera.yaml"), "--output", Path("pose.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("method linear (12 points)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("1σ rotation"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("mm"), std::string::npos) << run.out;

  const json result = json::parse(Read("pose.json"));
  EXPECT_EQ(result["method"], "linear");
  EXPECT_EQ(result["units"]["length"], "mm");
  const Pose T = PoseOf(result["T_camera_target"], 1e-3);
  EXPECT_LT(RotationError(T, scene.T_camera_target), 1e-9);
  EXPECT_LT((T.translation() - scene.T_camera_target.translation()).norm(), 1e-9);
  const json& t = result["T_camera_target"]["translation"];
  EXPECT_NEAR(t[2].get<double>(), 1000.0 * scene.T_camera_target.translation().z(), 1e-6);
  const json& q = result["T_camera_target"]["quaternion_wxyz"];
  const Eigen::Quaterniond truth(scene.T_camera_target.linear());
  EXPECT_NEAR(std::abs(q[0].get<double>() * truth.w() + q[1].get<double>() * truth.x() +
                       q[2].get<double>() * truth.y() + q[3].get<double>() * truth.z()),
              1.0, 1e-12);
  EXPECT_EQ(result["covariance"]["parameterization"], "right, (rx,ry,rz,tx,ty,tz)");
  EXPECT_EQ(result["covariance"]["pixel_sigma_source"], "estimated");
  ASSERT_EQ(result["covariance"]["matrix"].size(), 6u);
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) {
      EXPECT_EQ(result["covariance"]["matrix"][r][c], result["covariance"]["matrix"][c][r]);
    }
  }
  EXPECT_LT(result["reprojection_rms_px"].get<double>(), 1e-6);
  ASSERT_EQ(result["points"].size(), 12u);
  EXPECT_EQ(result["points"][0]["id"], "p5");
  EXPECT_EQ(result["points"][0]["residual_px"].size(), 2u);
}

TEST_F(PoseCommand, LinearRawWithFocalPairsByOrderAndHasNoCovariance) {
  const testing::PointView scene = [&] {
    std::mt19937_64 rng(2);
    pose::CameraModel pinhole = pose::CameraModel::Pinhole(1100.0);
    pinhole.cx = 600.0;
    pinhole.cy = 450.0;
    return testing::RandomScene(rng, 10, testing::PointShape::kVolume, pinhole);
  }();
  std::ostringstream object;
  object << std::setprecision(17) << "x,y,z\n";
  for (const Eigen::Vector3d& P : scene.object_points) {
    object << P.x() << ',' << P.y() << ',' << P.z() << '\n';
  }
  Write("object.csv", object.str());
  Write("image.csv", ImageCsv(scene, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, false));
  const cli_test::Outcome run =
      Hecal({"pose", "--points", Path("object.csv"), "--image-points", Path("image.csv"), "--focal",
             "1100", "--principal-point", "600,450", "--method", "linear-raw", "--output",
             Path("pose.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("no covariance"), std::string::npos) << run.out;
  const json result = json::parse(Read("pose.json"));
  EXPECT_EQ(result["method"], "linear-raw");
  EXPECT_EQ(result["units"]["length"], "m");
  EXPECT_FALSE(result.contains("covariance"));
  const Pose T = PoseOf(result["T_camera_target"], 1.0);
  EXPECT_LT(RotationError(T, scene.T_camera_target), 1e-9);
  EXPECT_EQ(result["points"][3]["id"], 4);  // by order: 1-based positions
}

TEST_F(PoseCommand, GivenPixelSigmaScalesTheCovariance) {
  const testing::PointView scene = Scene(12, testing::PointShape::kVolume, 3);
  Write("object.csv", ObjectCsvMm(scene));
  Write("image.csv", ImageCsv(scene, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, true));
  Write("camera.yaml", CameraYaml(scene.camera));
  std::vector<json> results;
  for (const char* sigma : {"0.5", "1"}) {
    const cli_test::Outcome run =
        Hecal({"pose", "--points", Path("object.csv"), "--image-points", Path("image.csv"),
               "--intrinsics", Path("camera.yaml"), "--method", "dlt", "--pixel-sigma", sigma,
               "--output", Path("pose.json")});
    ASSERT_EQ(run.code, 0) << run.err;
    results.push_back(json::parse(Read("pose.json")));
  }
  EXPECT_EQ(results[0]["covariance"]["pixel_sigma_source"], "given");
  EXPECT_EQ(results[0]["covariance"]["pixel_sigma"], 0.5);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(results[1]["covariance"]["matrix"][i][i].get<double>() /
                    results[0]["covariance"]["matrix"][i][i].get<double>(),
                4.0, 1e-9);
  }
}

TEST_F(PoseCommand, PlanarTargetNeedsDltOrIppe) {
  const testing::PointView scene = Scene(20, testing::PointShape::kPlane, 4);
  Write("object.csv", ObjectCsvMm(scene));
  std::vector<std::size_t> all(20);
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  Write("image.csv", ImageCsv(scene, all, true));
  Write("camera.yaml", CameraYaml(scene.camera));
  const std::vector<std::string> base = {
      "pose",         "--points",          Path("object.csv"), "--image-points", Path("image.csv"),
      "--intrinsics", Path("camera.yaml"), "--output",         Path("pose.json")};
  std::vector<std::string> linear = base;
  linear.insert(linear.end(), {"--method", "linear"});
  const cli_test::Outcome refused = Hecal(linear);
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--method ippe or dlt"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(Path("pose.json")));

  std::vector<std::string> dlt = base;
  dlt.insert(dlt.end(), {"--method", "dlt"});
  const cli_test::Outcome run = Hecal(dlt);
  ASSERT_EQ(run.code, 0) << run.err;
  const Pose T = PoseOf(json::parse(Read("pose.json"))["T_camera_target"], 1e-3);
  EXPECT_LT(RotationError(T, scene.T_camera_target), 1e-9);
}

TEST_F(PoseCommand, OpenCvMethodsNeedTheVisionLayer) {
  const testing::PointView scene = Scene(20, testing::PointShape::kPlane, 5);
  Write("object.csv", ObjectCsvMm(scene));
  std::vector<std::size_t> all(20);
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  Write("image.csv", ImageCsv(scene, all, true));
  Write("camera.yaml", CameraYaml(scene.camera));
  for (const char* method : {"ippe", "iterative"}) {
    const cli_test::Outcome run =
        Hecal({"pose", "--points", Path("object.csv"), "--image-points", Path("image.csv"),
               "--intrinsics", Path("camera.yaml"), "--method", method, "--output",
               Path(std::string(method) + ".json")});
#if defined(HECAL_HAVE_OPENCV_PEERS)
    ASSERT_EQ(run.code, 0) << run.err;
    const json result = json::parse(Read(std::string(method) + ".json"));
    EXPECT_EQ(result["method"], method);
    EXPECT_LT(RotationError(PoseOf(result["T_camera_target"], 1e-3), scene.T_camera_target), 1e-6);
    // OpenCV's closed form as it is; iterative is refined, so it carries a covariance.
    EXPECT_EQ(result.contains("covariance"), std::string(method) == "iterative");
#else
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find("needs the vision layer"), std::string::npos) << run.err;
#endif
  }
}

TEST_F(PoseCommand, BadInputExitsTwoWithFileAndLineAndWritesNothing) {
  const testing::PointView scene = Scene(8, testing::PointShape::kVolume, 6);
  Write("camera.yaml", CameraYaml(scene.camera));
  Write("image.csv", ImageCsv(scene, {0, 1, 2, 3, 4, 5, 6, 7}, true));
  const std::string good_object = ObjectCsvMm(scene);
  const auto run = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"pose",           "--points",        Path("object.csv"),
                                     "--image-points", Path("image.csv"), "--output",
                                     Path("pose.json")};
    args.insert(args.end(), extra.begin(), extra.end());
    return Hecal(args);
  };
  const std::vector<std::string> intrinsics = {"--intrinsics", Path("camera.yaml")};
  struct Case {
    std::string object;
    std::vector<std::string> flags;
    std::string expected;  // in stderr
  };
  std::string not_a_number = good_object;
  not_a_number[not_a_number.find("p2,") + 3] = 'x';
  std::string duplicate_id = good_object;
  duplicate_id[duplicate_id.find("p3,") + 1] = '1';
  const std::vector<Case> cases = {
      {not_a_number, intrinsics, "object.csv:5: x is not a finite number"},
      {duplicate_id, intrinsics, "object.csv:6: id 'p1' already used on line 4"},
      {"id,x,y,w\n1,2,3,4\n", intrinsics, "object.csv:1: unknown column 'w'"},
      {"id,x_mm,y_m,z_mm\n", intrinsics, "object.csv:1: the position columns have different"},
      {"# only a comment\n", intrinsics, "no object points in the file"},
      {good_object, {}, "--focal: give exactly one of focal and intrinsics"},
      {good_object, {"--focal", "-3"}, "--focal: expected a positive number"},
      {good_object, {"--focal", "1000", "--principal-point", "3"}, "expected 2 numbers, got 1"},
      {good_object,
       {"--intrinsics", Path("camera.yaml"), "--method", "nope"},
       "unknown method 'nope'"},
      {good_object,
       {"--intrinsics", Path("camera.yaml"), "--pixel-sigma", "0"},
       "--pixel-sigma: must be above 0 to 100 px"},
      {good_object, {"--intrinsics", Path("camera.yaml"), "--units", "ft"}, "unknown unit 'ft'"},
  };
  for (const Case& c : cases) {
    Write("object.csv", c.object);
    const cli_test::Outcome outcome = run(c.flags);
    EXPECT_EQ(outcome.code, 2) << c.expected << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find(c.expected), std::string::npos) << outcome.err;
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << "one line: " << outcome.err;
    EXPECT_FALSE(std::filesystem::exists(Path("pose.json"))) << c.expected;
  }

  // An image id that is not an object point, and a count mismatch when pairing by order.
  Write("object.csv", good_object);
  Write("image.csv", "id,u,v\np0,1,2\nq7,3,4\n");
  const cli_test::Outcome unknown_id = run(intrinsics);
  EXPECT_EQ(unknown_id.code, 2);
  EXPECT_NE(unknown_id.err.find("image.csv:3: image point id 'q7' is not in"), std::string::npos)
      << unknown_id.err;
  Write("image.csv", "u,v\n1,2\n3,4\n");
  const cli_test::Outcome mismatch = run(intrinsics);
  EXPECT_EQ(mismatch.code, 2);
  EXPECT_NE(mismatch.err.find("2 image points but 8 object points"), std::string::npos)
      << mismatch.err;
  EXPECT_FALSE(std::filesystem::exists(Path("pose.json")));
}

TEST_F(PoseCommand, UnitsFlagAppliesToColumnsWithoutSuffix) {
  const testing::PointView scene = Scene(10, testing::PointShape::kVolume, 7);
  std::ostringstream object, image;
  object << std::setprecision(17) << "id x y z\n";  // whitespace-separated
  image << std::setprecision(17) << "id,u,v\n";
  for (std::size_t k = 0; k < scene.object_points.size(); ++k) {
    const Eigen::Vector3d P = 1000.0 * scene.object_points[k];
    object << k << ' ' << P.x() << ' ' << P.y() << ' ' << P.z() << '\n';
    image << k << ',' << scene.pixels[k].x() << ',' << scene.pixels[k].y() << '\n';
  }
  Write("object.csv", object.str());
  Write("image.csv", image.str());
  Write("camera.yaml", CameraYaml(scene.camera));
  const cli_test::Outcome run =
      Hecal({"pose", "--points", Path("object.csv"), "--image-points", Path("image.csv"),
             "--intrinsics", Path("camera.yaml"), "--units", "mm", "--output", Path("pose.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  const json result = json::parse(Read("pose.json"));
  EXPECT_EQ(result["units"]["length"], "mm");
  EXPECT_LT(
      (PoseOf(result["T_camera_target"], 1e-3).translation() - scene.T_camera_target.translation())
          .norm(),
      1e-9);
}

// --intrinsics takes ViSP's camera XML (kud is plumb_bob's k1) and camera files without
// distortion (read as none, with a note): exact pixels of such cameras give back the true pose.
TEST_F(PoseCommand, VispXmlAndFilesWithoutDistortion) {
  pose::CameraModel visp = testing::SceneCamera();
  visp.distortion = {-0.08, 0.0, 0.0, 0.0, 0.0};
  pose::CameraModel plain = testing::SceneCamera();
  plain.distortion = {0.0, 0.0, 0.0, 0.0, 0.0};
  std::ostringstream xml;
  xml << std::setprecision(17) << "<?xml version=\"1.0\"?>\n<root>\n  <camera>\n"
      << "    <name>Camera</name>\n    <image_width>" << visp.width << "</image_width>\n"
      << "    <image_height>" << visp.height << "</image_height>\n    <model>\n"
      << "      <type>perspectiveProjWithDistortion</type>\n      <px>" << visp.fx << "</px>\n"
      << "      <py>" << visp.fy << "</py>\n      <u0>" << visp.cx << "</u0>\n      <v0>" << visp.cy
      << "</v0>\n      <kud>-0.08</kud>\n      <kdu>0.081</kdu>\n    </model>\n"
      << "  </camera>\n</root>\n";
  Write("camera.xml", xml.str());
  Write("plain.yaml", "fx: 1000\nfy: 995\ncx: 641.5\ncy: 478\n");
  for (const auto& [file, camera, note] :
       {std::tuple{"camera.xml", visp, "perspectiveProjWithDistortion, read as plumb_bob k1 = kud"},
        std::tuple{"plain.yaml", plain, "plain.yaml has no distortion: read as no distortion"}}) {
    SCOPED_TRACE(file);
    std::mt19937_64 rng(4);
    const testing::PointView scene =
        testing::RandomScene(rng, 12, testing::PointShape::kVolume, camera);
    Write("object.csv", ObjectCsvMm(scene));
    Write("image.csv", ImageCsv(scene, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, true));
    const cli_test::Outcome run =
        Hecal({"pose", "--points", Path("object.csv"), "--image-points", Path("image.csv"),
               "--intrinsics", Path(file), "--output", Path("pose.json")});
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_NE(run.out.find("note: "), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(note), std::string::npos) << run.out;
    const Pose T = PoseOf(json::parse(Read("pose.json"))["T_camera_target"], 1e-3);
    EXPECT_LT(RotationError(T, scene.T_camera_target), 1e-9);
    EXPECT_LT((T.translation() - scene.T_camera_target.translation()).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace hecal::cli
