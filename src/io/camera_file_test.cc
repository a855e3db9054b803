#include "hecal/io/camera_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/import_tabb.h"
#include "hecal/io/import_types.h"
#include "io_test_util.h"
#include "testing/thrown.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

pose::CameraModel ParseCamera(const std::string& text) {
  return ParseCameraFile(text, "camera.yaml").camera;
}

InputError CameraErrorOf(const std::string& text) {
  SCOPED_TRACE(text);
  return testing::Thrown<InputError>([&] { ParseCamera(text); });
}

void ExpectCameraError(const std::string& text, int line, const std::string& problem) {
  testing::ExpectInputError(CameraErrorOf(text), "camera.yaml", line, problem);
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
  hecal::UniformRealDistribution pixels(100.0, 3000.0), small(-0.5, 0.5);
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
    ExpectSame(ReadCameraFile(path).camera, camera);
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
  ExpectSame(ParseCamera("fx: 590.6972346\nfy: 592.84676713\ncx: 322.33104773\ncy: 247.40030325\n"
                         "width: 640\nheight: 480\n"
                         "distortion: {model: plumb_bob, coefficients: [0.15405498, -0.24916842, "
                         "0.00350791, -0.00110041, 0.0]}\n"),
             Moveit());
  // Four coefficients: k3 = 0; no image size: 0 (unknown).
  const pose::CameraModel four = ParseCamera(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\ndistortion:\n  model: plumb_bob\n"
      "  coefficients: [0.1, -0.2, 0.001, 0.002]\n");
  EXPECT_EQ(four.distortion, (std::array<double, 5>{0.1, -0.2, 0.001, 0.002, 0.0}));
  EXPECT_EQ(four.width, 0);
  EXPECT_EQ(four.height, 0);
}

TEST(CameraFile, ReadsWhatTheTabbImporterWrites) {
  const std::string dir = test_util::kSource + "/data/tabb-rwhe-dataset1/";
  const ImportedPoses tabb = ParseTabb(ReadFile(dir + "robot_cali.txt"), "robot_cali.txt",
                                       ReadFile(dir + "cali.txt"), "cali.txt");
  ASSERT_TRUE(tabb.intrinsics.has_value());
  const pose::CameraModel camera =
      ParseCamera(FormatIntrinsicsYaml(*tabb.intrinsics, {"from cali.txt"}));
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
  ExpectSame(ParseCamera(kOpenCvFile), Moveit());
  // OpenCV's rational model with k4..k6 = 0 (CALIB_RATIONAL_MODEL off) is plumb_bob.
  const pose::CameraModel eight = ParseCamera(
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
  ExpectSame(ParseCamera(kRosFile), Moveit());
}

TEST(CameraFile, ReadsAFile) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "hecal_camera_file_test.yml").string();
  WriteFileAtomically(path, kOpenCvFile);
  ExpectSame(ReadCameraFile(path).camera, Moveit());
  std::filesystem::remove(path);
  EXPECT_THROW(ReadCameraFile(path), InputError);
}

const std::string kDistortion = "distortion: {model: plumb_bob, coefficients: [0, 0, 0, 0, 0]}\n";

TEST(CameraFile, HecalLayoutErrors) {
  ExpectCameraError("", 0, "empty");
  ExpectCameraError("[1, 2]\n", 1, "not a map");
  ExpectCameraError("fx: 500\nfy: [500\n", 3, "not valid YAML");
  ExpectCameraError("width: 640\n", 0, "neither fx, fy (hecal) nor camera_matrix");
  ExpectCameraError("fx: 500\nfy: 500\ncx: 320\n" + kDistortion, 0, "no 'cy'");
  ExpectCameraError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nfocal: 3\n" + kDistortion, 5,
                    "unknown key \"focal\"");
  ExpectCameraError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nwidht: 640\n" + kDistortion, 5,
                    "(did you mean 'width'?)");
  ExpectCameraError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nfx: 501\n" + kDistortion, 5,
                    "key 'fx' is given twice");
  ExpectCameraError("fx: 0\nfy: 500\ncx: 320\ncy: 240\n" + kDistortion, 1, "fx is 0.0e+00");
  ExpectCameraError("fx: 500\nfy: -500\ncx: 320\ncy: 240\n" + kDistortion, 2,
                    "not a positive focal");
  ExpectCameraError("fx: .inf\nfy: 500\ncx: 320\ncy: 240\n" + kDistortion, 1,
                    "not a positive focal");
  ExpectCameraError("fx: 500\nfy: 500\ncx: .nan\ncy: 240\n" + kDistortion, 3, "not finite");
  ExpectCameraError("fx: 500\nfy: 500\ncx: abc\ncy: 240\n" + kDistortion, 3, "not a number");
  ExpectCameraError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nwidth: 640\n" + kDistortion, 5,
                    "has width but no height");
  ExpectCameraError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nwidth: 640\nheight: 0\n" + kDistortion, 6,
                    "the image size is 640 x 0");
  ExpectCameraError("fx: 500\nfy: 500\ncx: 320\ncy: 240\nwidth: 640.5\nheight: 480\n" + kDistortion,
                    5, "not a whole number");
  ExpectCameraError("fx: 500\nfy: 500\ncx: 320\ncy: 240\ndistortion: [0, 0, 0, 0, 0]\n", 5,
                    "distortion is not a map");
  ExpectCameraError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion: {model: equidistant, coefficients: [0, 0, 0, 0]}\n",
      5, "distortion model is \"equidistant\"; hecal supports plumb_bob only");
  ExpectCameraError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\ndistortion: {coefficients: [0, 0, 0, 0]}\n", 5,
      "no 'model'");
  ExpectCameraError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion:\n  model: plumb_bob\n  coeficients: [0, 0, 0, 0]\n",
      7, "unknown key \"coeficients\" in distortion (did you mean 'coefficients'?)");
  ExpectCameraError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion: {model: plumb_bob, coefficients: [0.1, 0.2, 0.3]}\n",
      5, "not a list of 4, 5, 8, 12 or 14 coefficients");
  ExpectCameraError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion: {model: plumb_bob, coefficients: [0.1, 0.2, 0, 0, 0, 0.01, 0, 0]}\n",
      5, "has k4 = 1.0e-02");
  ExpectCameraError(
      "fx: 500\nfy: 500\ncx: 320\ncy: 240\n"
      "distortion: {model: plumb_bob, coefficients: [0.1, .nan, 0, 0, 0]}\n",
      5, "coefficients[1] is not finite");
}

TEST(CameraFile, MatrixLayoutErrors) {
  const std::string d = "distortion_coefficients: [0, 0, 0, 0, 0]\n";
  ExpectCameraError("camera_matrix: [[500, 0, 320], [0, 500, 240]]\n" + d, 1, "2x3, not 3x3");
  ExpectCameraError("camera_matrix: [[500, 0.5, 320], [0, 500, 240], [0, 0, 1]]\n" + d, 1,
                    "it has skew 5.0e-01");
  ExpectCameraError("camera_matrix: [[500, 0, 320], [0, 500, 240], [0, 0, 2]]\n" + d, 1,
                    "not of the form [fx 0 cx; 0 fy cy; 0 0 1]");
  ExpectCameraError("camera_matrix: [[-500, 0, 320], [0, 500, 240], [0, 0, 1]]\n" + d, 1,
                    "fx is -5.0e+02");
  ExpectCameraError("camera_matrix: [[500, 0, 320], [0, 500, 240], [0, 0, 1]]\nfx: 500\n" + d, 2,
                    "both camera_matrix and fx");
  ExpectCameraError(
      "camera_matrix: [[500, 0, 320], [0, 500, 240], [0, 0, 1]]\n"
      "distortion_coefficients: [[0, 0], [0, 0]]\n",
      2, "2x2, not a list");
  ExpectCameraError(
      "camera_matrix: [[500, 0, 320], [0, 500, 240], [0, 0, 1]]\n" + d + "image_height: 480\n", 3,
      "has image_height but no image_width");
  std::string rational = kRosFile;
  rational.replace(rational.find("plumb_bob"), 9, "rational_polynomial");
  ExpectCameraError(rational, 8,
                    "distortion_model is \"rational_polynomial\"; hecal supports plumb_bob only");
  std::string dt = kOpenCvFile;
  dt.replace(dt.find("dt: d"), 5, "dt: u");
  ExpectCameraError(dt, 9, "camera_matrix has dt \"u\"");
}

// A file without distortion reads as no distortion, and says so; a file with it has no note.
TEST(CameraFile, MissingDistortionIsReadAsNoneWithANote) {
  const CameraFile hecal = ParseCameraFile("fx: 500\nfy: 510\ncx: 320\ncy: 240\n", "cam.yaml");
  EXPECT_EQ(hecal.camera.fy, 510.0);
  EXPECT_EQ(hecal.camera.distortion, (std::array<double, 5>{0, 0, 0, 0, 0}));
  EXPECT_EQ(hecal.notes,
            std::vector<std::string>{"cam.yaml has no distortion: read as no distortion"});
  const CameraFile opencv = ParseCameraFile(
      "%YAML:1.0\ncamera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
      "   data: [500., 0., 320., 0., 510., 240., 0., 0., 1.]\n",
      "ocv.yml");
  EXPECT_EQ(opencv.camera.cx, 320.0);
  EXPECT_EQ(opencv.camera.distortion, (std::array<double, 5>{0, 0, 0, 0, 0}));
  EXPECT_EQ(opencv.notes, std::vector<std::string>{
                              "ocv.yml has no distortion_coefficients: read as no distortion"});
  std::string ros = kRosFile;
  const size_t begin = ros.find("distortion_coefficients:");
  ros.erase(begin, ros.find("rectification_matrix:") - begin);
  EXPECT_THAT(ParseCameraFile(ros, "ros.yaml").notes,
              ::testing::ElementsAre("ros.yaml has no distortion_coefficients: read as no "
                                     "distortion"));
  EXPECT_TRUE(ParseCameraFile(kOpenCvFile, "ocv.yml").notes.empty());
  EXPECT_TRUE(ParseCameraFile(kRosFile, "ros.yaml").notes.empty());
}

// ViSP's apps/calibration/hand-eye/data-eye-in-hand/franka_camera.xml (vpXmlParserCamera::save):
// one camera, the model with distortion only (kud = -0).
const std::string kVispFranka = R"(<?xml version="1.0"?>
<root>
  <!--This file stores intrinsic camera parameters used
   in the vpCameraParameters Class of ViSP available
   at https://visp.inria.fr/download/ .
   It can be read with the parse method of
   the vpXmlParserCamera class.-->
  <camera>
    <!--Name of the camera-->
    <name>Camera</name>
    <!--Size of the image on which camera calibration was performed-->
    <image_width>640</image_width>
    <image_height>480</image_height>
    <!--Intrinsic camera parameters computed for each projection model-->
    <model>
      <!--Projection model type-->
      <type>perspectiveProjWithDistortion</type>
      <!--Pixel ratio-->
      <px>607.5931396484375</px>
      <py>607.574951171875</py>
      <!--Principal point-->
      <u0>323.46282958984375</u0>
      <v0>243.25529479980469</v0>
      <!--Undistorted to distorted distortion parameter-->
      <kud>-0</kud>
      <!--Distorted to undistorted distortion parameter-->
      <kdu>0</kdu>
    </model>
  </camera>
</root>
)";

// The layout of ViSP's tutorial/image/camera.xml: both models, with distortion (kud, kdu), and
// additional information from the calibration.
const std::string kVispBoth = R"(<?xml version="1.0"?>
<root>
  <camera>
    <name>Camera</name>
    <image_width>640</image_width>
    <image_height>480</image_height>
    <model>
      <type>perspectiveProjWithoutDistortion</type>
      <px>557.25193286403885</px>
      <py>561.17762050162196</py>
      <u0>360.07544847291069</u0>
      <v0>235.52403615842633</v0>
    </model>
    <model>
      <type>perspectiveProjWithDistortion</type>
      <px>536.98240404421483</px>
      <py>537.41963884658458</py>
      <u0>344.0958214339521</u0>
      <v0>235.17921083438051</v0>
      <kud>-0.26726720925264602</kud>
      <kdu>0.30810929494420369</kdu>
    </model>
    <additional_information>
      <date>2020/05/13 09:43:08</date>
      <nb_calibration_images>13</nb_calibration_images>
      <camera_poses>
        <cMo>-0.08850223516  -0.1086282928  0.4229664739  0.1408148834  0.2208825139  0.01502620077</cMo>
      </camera_poses>
    </additional_information>
  </camera>
</root>
)";

TEST(CameraFile, VispXmlValuesAreTheFilesValues) {
  const CameraFile franka = ParseCameraFile(kVispFranka, "franka_camera.xml");
  EXPECT_EQ(franka.camera.fx, 607.5931396484375);
  EXPECT_EQ(franka.camera.fy, 607.574951171875);
  EXPECT_EQ(franka.camera.cx, 323.46282958984375);
  EXPECT_EQ(franka.camera.cy, 243.25529479980469);
  EXPECT_EQ(franka.camera.width, 640);
  EXPECT_EQ(franka.camera.height, 480);
  EXPECT_EQ(franka.camera.distortion, (std::array<double, 5>{0, 0, 0, 0, 0}));
  ASSERT_EQ(franka.notes.size(), 1u);
  EXPECT_THAT(franka.notes[0],
              HasSubstr("franka_camera.xml: ViSP camera \"Camera\": model "
                        "perspectiveProjWithDistortion, read as plumb_bob k1 = kud = 0.0e+00 "));

  // Both models: the one with distortion is used, kud → k1, kdu unused.
  const CameraFile both = ParseCameraFile(kVispBoth, "camera.xml");
  EXPECT_EQ(both.camera.fx, 536.98240404421483);
  EXPECT_EQ(both.camera.fy, 537.41963884658458);
  EXPECT_EQ(both.camera.cx, 344.0958214339521);
  EXPECT_EQ(both.camera.cy, 235.17921083438051);
  EXPECT_EQ(both.camera.distortion,
            (std::array<double, 5>{-0.26726720925264602, 0.0, 0.0, 0.0, 0.0}));
  EXPECT_THAT(both.notes[0], HasSubstr("the model without distortion is ignored"));

  // Only the model without distortion: no distortion, and a note.
  std::string without = kVispBoth;
  const size_t begin = without.find("    <model>\n      <type>perspectiveProjWithDistortion");
  without.erase(begin, without.find("</model>", begin) + 9 - begin);
  const CameraFile plain = ParseCameraFile(without, "camera.xml");
  EXPECT_EQ(plain.camera.fx, 557.25193286403885);
  EXPECT_EQ(plain.camera.cy, 235.52403615842633);
  EXPECT_FALSE(plain.camera.HasDistortion());
  EXPECT_THAT(plain.notes,
              ::testing::ElementsAre("camera.xml: ViSP camera \"Camera\" has only the model "
                                     "perspectiveProjWithoutDistortion: read as no distortion"));
}

// ViSP's model, written out from vpMeterPixelConversion::convertPointWithDistortion:
// u = u0 + px·x·(1 + kud·r²), v = v0 + py·y·(1 + kud·r²) for normalised (x, y). hecal's plumb_bob
// projection of the camera read from the XML gives the same pixels.
TEST(CameraFile, VispDistortionMapsOntoPlumbBob) {
  const CameraFile both = ParseCameraFile(kVispBoth, "camera.xml");
  const double px = 536.98240404421483, py = 537.41963884658458, u0 = 344.0958214339521,
               v0 = 235.17921083438051, kud = -0.26726720925264602;
  for (const Eigen::Vector3d& point :
       {Eigen::Vector3d(0.1, -0.05, 1.0), Eigen::Vector3d(-0.3, 0.2, 0.8),
        Eigen::Vector3d(0.02, 0.31, 0.5)}) {
    const double x = point.x() / point.z(), y = point.y() / point.z();
    const double radial = 1.0 + kud * (x * x + y * y);
    const Eigen::Vector2d visp(u0 + px * x * radial, v0 + py * y * radial);
    EXPECT_LT((pose::Project(both.camera, point) - visp).norm(), 1e-9) << point.transpose();
  }
}

// Told apart by content, not by name: XML in a .yaml file is read as XML.
TEST(CameraFile, XmlIsDetectedByContent) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "hecal_camera_file_test_visp.yaml").string();
  WriteFileAtomically(path, "\n  " + kVispFranka);
  EXPECT_EQ(ReadCameraFile(path).camera.fx, 607.5931396484375);
  std::filesystem::remove(path);
  std::string no_declaration = kVispFranka;
  no_declaration.erase(0, no_declaration.find("<root>"));
  EXPECT_EQ(ParseCamera(no_declaration).cx, 323.46282958984375);
}

void ExpectXmlError(const std::string& xml, int line, const std::string& problem) {
  testing::ExpectInputError(CameraErrorOf(xml), "camera.yaml", line, problem);
}

std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(CameraFile, VispXmlErrors) {
  const std::string& f = kVispFranka;
  ExpectXmlError(Replaced(f, "</px>", "</pz>"), 19, "not valid XML");
  ExpectXmlError(Replaced(f, "<root>", "<cameras>"), 2, "not valid XML");  // </root> unmatched
  std::string other_root = Replaced(Replaced(f, "<root>", "<cameras>"), "</root>", "</cameras>");
  ExpectXmlError(other_root, 2, "the XML's top element is <cameras>, not ViSP's <root>");
  ExpectXmlError(Replaced(f, "<px>607.5931396484375</px>", "<px>6O7.5</px>"), 19,
                 "<px> is \"6O7.5\", not a number");
  ExpectXmlError(Replaced(f, "<px>607.5931396484375</px>", ""), 15,
                 "perspectiveProjWithDistortion model has no <px>");
  ExpectXmlError(Replaced(f, "<kdu>0</kdu>", "<kdu>0</kdu><kdu>1</kdu>"), 27,
                 "<model> has two <kdu> elements");
  ExpectXmlError(Replaced(f, "<kud>-0</kud>", "<k1>0</k1>"), 25, "unknown element <k1> in <model>");
  ExpectXmlError(Replaced(f, "perspectiveProjWithDistortion", "ProjWithKannalaBrandtDistortion"),
                 17, "model type \"ProjWithKannalaBrandtDistortion\" is not one hecal reads");
  ExpectXmlError(Replaced(f, "<name>Camera</name>", "<nom>Camera</nom>"), 10,
                 "unknown element <nom> in <camera>");
  ExpectXmlError(Replaced(f, "    <image_height>480</image_height>\n", ""), 12,
                 "<camera> has image_width but no image_height");
  ExpectXmlError(Replaced(f, "<image_width>640</image_width>", "<image_width>640.5</image_width>"),
                 12, "<image_width> is \"640.5\", not a whole number of pixels >= 1");
  ExpectXmlError(Replaced(f, "<px>607.5931396484375</px>", "<px>-607.5</px>"), 19,
                 "fx is -6.1e+02");
  ExpectXmlError(Replaced(f, "<kud>-0</kud>", "<kud>nan</kud>"), 25, "<kud> is not finite");
  ExpectXmlError(Replaced(f, "<px>607.5931396484375</px>", "<px><v>1</v></px>"), 19,
                 "<px> holds elements, not a value");
  ExpectXmlError(Replaced(f, "<type>perspectiveProjWithDistortion</type>", "<px>1</px>"), 19,
                 "<model> has two <px> elements");
  ExpectXmlError("<?xml version=\"1.0\"?>\n<root>\n</root>\n", 2, "<root> has no <camera>");
  ExpectXmlError("<root><camera><name>A</name></camera></root>", 1, "<camera> has no <model>");
}

// Several <camera> entries: an error listing them, unless they all read the same.
TEST(CameraFile, VispXmlWithSeveralCameras) {
  const size_t begin = kVispFranka.find("  <camera>");
  const size_t end = kVispFranka.find("</root>");
  const std::string camera = kVispFranka.substr(begin, end - begin);
  const std::string twice = kVispFranka.substr(0, end) + camera + "</root>\n";
  EXPECT_EQ(ParseCamera(twice).fx, 607.5931396484375);
  const std::string hd = Replaced(Replaced(Replaced(camera, "640", "1280"), "480", "720"),
                                  "<name>Camera</name>", "<name>Camera HD</name>");
  const InputError error = CameraErrorOf(kVispFranka.substr(0, end) + hd + "</root>\n");
  testing::ExpectInputError(error, "camera.yaml", 0,
                            "has 2 different <camera> entries: \"Camera\" 640x480, \"Camera HD\" "
                            "1280x720");
  EXPECT_THAT(error.fix(), HasSubstr("keep only the camera"));
}

}  // namespace
}  // namespace hecal::io
