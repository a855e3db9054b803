#include "hecal/io/camera_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/import_tabb.h"
#include "hecal/io/import_types.h"
#include "testing/thrown.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

const std::string kSource = std::string(HECAL_SOURCE_DIR);

pose::CameraModel Parse(const std::string& text) {
  return ParseCameraYaml(text, "camera.yaml");
}

InputError ErrorOf(const std::string& text) {
  SCOPED_TRACE(text);
  return testing::Thrown<InputError>([&] { Parse(text); });
}

void ExpectError(const std::string& text, int line, const std::string& problem) {
  testing::ExpectInputError(ErrorOf(text), "camera.yaml", line, problem);
}

// The moveit ChArUco camera (data/moveit-calibration/SOURCE.md).
pose::CameraModel Moveit() {
  pose::CameraModel camera;
  camera.fx = 590.6972346;
  camera.fy = 592.84676713;
  camera.cx = 322.33104773;
  camera.cy = 247.40030325;
  camera.width = 640;
  camera.height = 480;
  camera.distortion = {0.15405498, -0.24916842, 0.00350791, -0.00110041, 0.0};
  return camera;
}

void ExpectSame(const pose::CameraModel& a, const pose::CameraModel& b) {
  EXPECT_EQ(a.fx, b.fx);
  EXPECT_EQ(a.fy, b.fy);
  EXPECT_EQ(a.cx, b.cx);
  EXPECT_EQ(a.cy, b.cy);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.distortion, b.distortion);
}

TEST(CameraFile, RoundTripIsExact) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> pixels(100.0, 3000.0), small(-0.5, 0.5);
  const std::string path =
      (std::filesystem::temp_directory_path() / "hecal_camera_file_test.yaml").string();
  for (int trial = 0; trial < 50; ++trial) {
    pose::CameraModel camera;
    camera.fx = pixels(random);
    camera.fy = pixels(random);
    camera.cx = pixels(random) / 2;
    camera.cy = pixels(random) / 2;
    if (trial % 2 == 0) {  // with and without the image size
      camera.width = 1280 + trial;
      camera.height = 960;
    }
    for (double& k : camera.distortion) k = small(random) * std::pow(10.0, -(trial % 7));
    WriteCameraFile(path, camera, {"trial " + std::to_string(trial), "second comment"});
    ExpectSame(ReadCameraFile(path), camera);
  }
  std::filesystem::remove(path);
}

TEST(CameraFile, WritesHecalLayout) {
  EXPECT_EQ(FormatCameraYaml(Moveit(), {"moveit"}),
            "# moveit\nfx: 590.6972346\nfy: 592.84676713\ncx: 322.33104773\ncy: 247.40030325\n"
            "width: 640\nheight: 480\ndistortion:\n  model: plumb_bob\n  coefficients: "
            "[0.15405498, -0.24916842, 0.00350791, -0.00110041, 0]\n");
}

TEST(CameraFile, HecalLayout) {
  ExpectSame(Parse("fx: 590.6972346\nfy: 592.84676713\ncx: 322.33104773\ncy: 247.40030325\n"
                   "width: 640\nheight: 480\n"
                   "distortion: {model: plumb_bob, coefficients: [0.15405498, -0.24916842, "
                   "0.00350791, -0.00110041, 0.0]}\n"),
             Moveit());
  // Four coefficients: k3 = 0; no image size: 0 (unknown).
  const pose::CameraModel four = Parse(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\ndistortion:\n  model: plumb_bob\n"
      "  coefficients: [0.1, -0.2, 0.001, 0.002]\n");
  EXPECT_EQ(four.distortion, (std::array<double, 5>{0.1, -0.2, 0.001, 0.002, 0.0}));
  EXPECT_EQ(four.width, 0);
  EXPECT_EQ(four.height, 0);
}

TEST(CameraFile, ReadsWhatTheTabbImporterWrites) {
  const std::string dir = kSource + "/data/tabb-rwhe-dataset1/";
  const ImportedPoses tabb = ParseTabb(ReadFile(dir + "robot_cali.txt"), "robot_cali.txt",
                                       ReadFile(dir + "cali.txt"), "cali.txt");
  ASSERT_TRUE(tabb.intrinsics.has_value());
  const pose::CameraModel camera = Parse(FormatIntrinsicsYaml(*tabb.intrinsics, {"from cali.txt"}));
  EXPECT_EQ(camera.fx, tabb.intrinsics->fx);
  EXPECT_EQ(camera.cy, tabb.intrinsics->cy);
  ASSERT_EQ(tabb.intrinsics->distortion.size(), 5u);
  for (size_t k = 0; k < 5; ++k) EXPECT_EQ(camera.distortion[k], tabb.intrinsics->distortion[k]);
}

// As cv::FileStorage (OpenCV 4.6) writes it: K, D of the moveit camera, plus other keys that the
// calibration sample writes and hecal ignores.
const std::string kOpenCvFile = R"(%YAML:1.0
---
calibration_time: Thu 01 Jan 2024
image_width: 640
image_height: 480
camera_matrix: !!opencv-matrix
   rows: 3
   cols: 3
   dt: d
   data: [ 5.9069723460000000e+02, 0., 3.2233104773000002e+02, 0.,
       5.9284676712999999e+02, 2.4740030325000001e+02, 0., 0., 1. ]
distortion_coefficients: !!opencv-matrix
   rows: 5
   cols: 1
   dt: d
   data: [ 1.5405498000000001e-01, -2.4916842000000000e-01,
       3.5079099999999999e-03, -1.1004100000000000e-03, 0. ]
avg_reprojection_error: 3.1000000000000000e-01
)";

TEST(CameraFile, OpenCvFileStorageLayout) {
  ExpectSame(Parse(kOpenCvFile), Moveit());
  // OpenCV's rational model with k4..k6 = 0 (CALIB_RATIONAL_MODEL off) is plumb_bob.
  const pose::CameraModel eight = Parse(
      "%YAML:1.0\ncamera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
      "   data: [500., 0., 320., 0., 510., 240., 0., 0., 1.]\n"
      "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 8\n   dt: d\n"
      "   data: [0.1, 0.2, 0.3, 0.4, 0.5, 0., 0., 0.]\n");
  EXPECT_EQ(eight.fy, 510.0);
  EXPECT_EQ(eight.distortion, (std::array<double, 5>{0.1, 0.2, 0.3, 0.4, 0.5}));
  EXPECT_EQ(eight.width, 0);
}

// camera_calibration_parsers' layout of sensor_msgs/CameraInfo.
const std::string kRosFile = R"(image_width: 640
image_height: 480
camera_name: narrow_stereo
camera_matrix:
  rows: 3
  cols: 3
  data: [590.6972346, 0, 322.33104773, 0, 592.84676713, 247.40030325, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [0.15405498, -0.24916842, 0.00350791, -0.00110041, 0.0]
rectification_matrix:
  rows: 3
  cols: 3
  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]
projection_matrix:
  rows: 3
  cols: 4
  data: [590.6972346, 0, 322.33104773, 0, 0, 592.84676713, 247.40030325, 0, 0, 0, 1, 0]
)";

TEST(CameraFile, RosCameraInfoLayout) {
  ExpectSame(Parse(kRosFile), Moveit());
}

TEST(CameraFile, ReadsAFile) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "hecal_camera_file_test.yml").string();
  WriteFileAtomically(path, kOpenCvFile);
  ExpectSame(ReadCameraFile(path), Moveit());
  std::filesystem::remove(path);
  EXPECT_THROW(ReadCameraFile(path), InputError);
}

const std::string kDistortion = "distortion: {model: plumb_bob, coefficients: [0, 0, 0, 0, 0]}\n";

TEST(CameraFile, HecalLayoutErrors) {
  ExpectError("", 0, "empty");
  ExpectError("[1, 2]\n", 1, "not a map");
  ExpectError("fx: 500\nfy: [500\n", 3, "not valid YAML");
  ExpectError("width: 640\n", 0, "neither fx, fy (hecal) nor camera_matrix");
  ExpectError("fx: 500\nfy: 500\ncx: 320\n" + kDistortion, 0, "no 'cy'");
  ExpectError("fx: 500\nfy: 500\ncx: 320\ncy: 240\n", 0, "no 'distortion'");
  ExpectError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nfocal: 3\n" + kDistortion, 5,
              "unknown key \"focal\"");
  ExpectError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nwidht: 640\n" + kDistortion, 5,
              "(did you mean 'width'?)");
  ExpectError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nfx: 501\n" + kDistortion, 5,
              "key 'fx' is given twice");
  ExpectError("fx: 0\nfy: 500\ncx: 320\ncy: 240\n" + kDistortion, 1, "fx is 0.0e+00");
  ExpectError("fx: 500\nfy: -500\ncx: 320\ncy: 240\n" + kDistortion, 2, "not a positive focal");
  ExpectError("fx: .inf\nfy: 500\ncx: 320\ncy: 240\n" + kDistortion, 1, "not a positive focal");
  ExpectError("fx: 500\nfy: 500\ncx: .nan\ncy: 240\n" + kDistortion, 3, "not finite");
  ExpectError("fx: 500\nfy: 500\ncx: abc\ncy: 240\n" + kDistortion, 3, "not a number");
  ExpectError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nwidth: 640\n" + kDistortion, 5,
              "has width but no height");
  ExpectError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nwidth: 640\nheight: 0\n" + kDistortion, 6,
              "the image size is 640 x 0");
  ExpectError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nwidth: 640.5\nheight: 480\n" + kDistortion, 5,
              "not a whole number");
  ExpectError("fx: 500\nfy: 500\ncx: 320\ncy: 240\ndistortion: [0, 0, 0, 0, 0]\n", 5,
              "distortion is not a map");
  ExpectError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion: {model: equidistant, coefficients: [0, 0, 0, 0]}\n",
      5, "distortion model is \"equidistant\"; hecal supports plumb_bob only");
  ExpectError("fx: 500\nfy: 500\ncx: 320\ncy: 240\ndistortion: {coefficients: [0, 0, 0, 0]}\n", 5,
              "no 'model'");
  ExpectError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion:\n  model: plumb_bob\n  coeficients: [0, 0, 0, 0]\n",
      7, "unknown key \"coeficients\" in distortion (did you mean 'coefficients'?)");
  ExpectError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion: {model: plumb_bob, coefficients: [0.1, 0.2, 0.3]}\n",
      5, "not a list of 4, 5, 8, 12 or 14 coefficients");
  ExpectError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion: {model: plumb_bob, coefficients: [0.1, 0.2, 0, 0, 0, 0.01, 0, 0]}\n",
      5, "has k4 = 1.0e-02");
  ExpectError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion: {model: plumb_bob, coefficients: [0.1, .nan, 0, 0, 0]}\n",
      5, "coefficients[1] is not finite");
}

TEST(CameraFile, MatrixLayoutErrors) {
  const std::string d = "distortion_coefficients: [0, 0, 0, 0, 0]\n";
  ExpectError("camera_matrix: [[500, 0, 320], [0, 500, 240]]\n" + d, 1, "2x3, not 3x3");
  ExpectError("camera_matrix: [[500, 0.5, 320], [0, 500, 240], [0, 0, 1]]\n" + d, 1,
              "it has skew 5.0e-01");
  ExpectError("camera_matrix: [[500, 0, 320], [0, 500, 240], [0, 0, 2]]\n" + d, 1,
              "not of the form [fx 0 cx; 0 fy cy; 0 0 1]");
  ExpectError("camera_matrix: [[-500, 0, 320], [0, 500, 240], [0, 0, 1]]\n" + d, 1,
              "fx is -5.0e+02");
  ExpectError("camera_matrix: [[500, 0, 320], [0, 500, 240], [0, 0, 1]]\n", 1,
              "no 'distortion_coefficients'");
  ExpectError("camera_matrix: [[500, 0, 320], [0, 500, 240], [0, 0, 1]]\nfx: 500\n" + d, 2,
              "both camera_matrix and fx");
  ExpectError(
      "camera_matrix: [[500, 0, 320], [0, 500, 240], [0, 0, 1]]\n"
      "distortion_coefficients: [[0, 0], [0, 0]]\n",
      2, "2x2, not a list");
  ExpectError(
      "camera_matrix: [[500, 0, 320], [0, 500, 240], [0, 0, 1]]\n" + d + "image_height: 480\n", 3,
      "has image_height but no image_width");
  std::string rational = kRosFile;
  rational.replace(rational.find("plumb_bob"), 9, "rational_polynomial");
  ExpectError(rational, 8,
              "distortion_model is \"rational_polynomial\"; hecal supports plumb_bob only");
  std::string dt = kOpenCvFile;
  dt.replace(dt.find("dt: d"), 5, "dt: u");
  ExpectError(dt, 9, "camera_matrix has dt \"u\"");
}

}  // namespace
}  // namespace hecal::io
