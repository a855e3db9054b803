// The real rwhe-kuka2 images (28 views, 1920×1200, chessboard 24×17 inner corners, 15 mm;
// data/rwhe-kuka2/SOURCE.md) end to end through the CLI: `hecal detect` then `hecal calibrate
// --camera`, with the reference intrinsics and with intrinsics estimated from the images; and
// `hecal calibrate --images` in one step. Truth:
// SOURCE.md's reference X = T_gripper_camera (OpenCV PARK, confirmed by TSAI/HORAUD/DANIILIDIS/
// SHAH to 1 mm): rvec (−1.20742, 1.28362, −1.18276), t = (0.01439, −0.10790, −0.08187) m, with its
// suggested tolerance of 0.1° / 2 mm; and its calibrateCamera reference
// K = [1056.2855 0 958.7994; 0 1056.4172 586.9487], RMS 0.074 px.
// Built with the vision layer only. Each run detects the 28 images in about 2 s on 2 cores.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "cli_test_util.h"
#include "testing/csv_reader.h"

namespace hecal::cli {
namespace {
#if defined(HECAL_HAVE_OPENCV_PEERS)  // `hecal detect` needs the vision layer

using cli_test::CliTest;
using cli_test::Hecal;

constexpr const char* kReferenceCamera =
    "fx: 1056.2855\nfy: 1056.4172\ncx: 958.7994\ncy: 586.9487\nwidth: 1920\nheight: 1200\n"
    "distortion:\n  model: plumb_bob\n"
    "  coefficients: [-0.131337, 0.099230, 0.000133, 0.000312, -0.049132]\n";

class Kuka2Images : public CliTest {
 protected:
  std::string DataDir() const { return std::string(HECAL_SOURCE_DIR) + "/data/rwhe-kuka2"; }

  std::string TargetFile() const {
    return Write("target.yaml", "type: chessboard\ncols: 24\nrows: 17\nsquare: 0.015\n");
  }

  // X of a result file against SOURCE.md's reference, within its suggested 0.1° / 2 mm. The
  // reference is OpenCV's at the described 15 mm squares, so the runs compared with it pass
  // --target-scale stated (the board measures 95.8 %: TheBoardIsMeasuredSmallerThanDescribed).
  static void ExpectReferenceX(const nlohmann::json& result) {
    Eigen::Matrix4d X;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) X(r, c) = result["X"]["matrix"][r][c].get<double>();
    }
    const Eigen::Matrix3d R_reference =
        Eigen::AngleAxisd(Eigen::Vector3d(-1.20742, 1.28362, -1.18276).norm(),
                          Eigen::Vector3d(-1.20742, 1.28362, -1.18276).normalized())
            .toRotationMatrix();
    const Eigen::Vector3d t_reference(0.01439, -0.10790, -0.08187);
    const double rotation_deg =
        Eigen::AngleAxisd(R_reference.transpose() * X.topLeftCorner<3, 3>()).angle() * 180.0 /
        std::numbers::pi;
    EXPECT_LT(rotation_deg, 0.1);
    EXPECT_LT((X.topRightCorner<3, 1>() - t_reference).norm(), 0.002);
  }

  // Runs detect (with `intrinsics`, or estimating them when empty), then calibrate, and
  // checks X against the reference.
  void DetectAndCalibrate(const std::string& intrinsics) {
    std::vector<std::string> args = {"detect",     "--images", DataDir() + "/images", "--target",
                                     TargetFile(), "--output", Path("camera.csv")};
    if (!intrinsics.empty()) {
      args.push_back("--intrinsics");
      args.push_back(intrinsics);
    }
    const cli_test::Outcome detect = Hecal(args);
    ASSERT_EQ(detect.code, 0) << detect.err;
    ASSERT_EQ(csv_test::ReadCsv(Path("camera.csv")).rows.size(), 28u) << detect.out;

    // RobotPosesVec.txt: 28 lines of 16 numbers (row-major T_base_gripper, metres), paired by
    // order with the images sorted by name (im_01 ... im_28).
    const cli_test::Outcome calibrate = Hecal(
        {"calibrate", "--robot", DataDir() + "/RobotPosesVec.txt", "--camera", Path("camera.csv"),
         "--setup", "eye-in-hand", "--target-scale", "stated", "--output", Path("result.json")});
    ASSERT_EQ(calibrate.code, 0) << calibrate.err;
    ExpectReferenceX(nlohmann::json::parse(Read("result.json")));
  }
};

TEST_F(Kuka2Images, WithTheReferenceIntrinsics) {
  DetectAndCalibrate(Write("camera.yaml", kReferenceCamera));
}

// The estimate against calibrateCamera's reference, which used findChessboardCornersSB (ACCURACY)
// corners; hecal detects with findChessboardCorners and its own edge refinement, so the two
// differ by the detectors' small systematic differences: measured 0.008 / 0.038 / 0.015 /
// 0.093 px for fx / fy / cx / cy, within 3 of the estimate's own 1σ (0.069 / 0.068 / 0.052 /
// 0.040 px), which is what is asserted. RMS reprojection error ≤ 0.1 px.
TEST_F(Kuka2Images, WithIntrinsicsEstimatedFromTheImages) {
  DetectAndCalibrate("");
  const std::string yaml = Read("camera.camera.yaml");
  const auto value = [&yaml](const std::string& key) {
    const std::size_t at = yaml.find("\n" + key + ": ");
    EXPECT_NE(at, std::string::npos) << key << " missing in\n" << yaml;
    return std::stod(yaml.substr(at + key.size() + 3));
  };
  EXPECT_NEAR(value("fx"), 1056.2855, 3 * 0.069);
  EXPECT_NEAR(value("fy"), 1056.4172, 3 * 0.068);
  EXPECT_NEAR(value("cx"), 958.7994, 3 * 0.052);
  EXPECT_NEAR(value("cy"), 586.9487, 3 * 0.040);
  const std::size_t rms = yaml.find("RMS reprojection error ");
  ASSERT_NE(rms, std::string::npos) << yaml;
  EXPECT_LE(std::stod(yaml.substr(rms + 23)), 0.1);
}

// `hecal calibrate --images` in one step: intrinsics estimated (RMS ≤ 0.1 px), every image used,
// X within the reference's tolerance, per-image reprojection RMS in the result.
TEST_F(Kuka2Images, CalibrateFromTheImagesInOneStep) {
  const cli_test::Outcome run =
      Hecal({"calibrate", "--images", DataDir() + "/images", "--target", TargetFile(), "--robot",
             DataDir() + "/RobotPosesVec.txt", "--setup", "eye-in-hand", "--target-scale", "stated",
             "--output", Path("result.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(Read("result.json"));
  ExpectReferenceX(result);
  EXPECT_EQ(result["refinement"], "reprojection");
  const nlohmann::json& images = result["images"];
  EXPECT_LE(images["intrinsics"]["rms_px"].get<double>(), 0.1);
  ASSERT_EQ(images["per_image"].size(), 28u);
  EXPECT_EQ(images["per_image"][0]["id"], "im_01");
  EXPECT_LE(images["reprojection_rms_px"].get<double>(), 0.1);
  EXPECT_TRUE(result["stations"]["rejected"].empty());
  ASSERT_TRUE(result.contains("covariance"));
  // 1σ of X from the joint refinement: ~0.02° and ~0.2 mm per axis; the reference is 0.07° and
  // 0.3 mm away, consistent with that.
  const double sigma_tx = std::sqrt(result["covariance"]["X"][3][3].get<double>());
  EXPECT_GT(sigma_tx, 0.02e-3);
  EXPECT_LT(sigma_tx, 1e-3);
}

// The default run measures the board (docs/target-scale.md, data/rwhe-kuka2/SOURCE.md): 95.8 %
// ± 0.75 % of the described 15 mm, named in a warning; X at the measured size lies within 3σ
// (along the gripper's axes) of hecal's board-free answer, (33.6, −102.7, −76.2) mm
// (docs/global.md), which the stated-size X misses by ~20 mm.
TEST_F(Kuka2Images, TheBoardIsMeasuredSmallerThanDescribed) {
  const cli_test::Outcome run = Hecal({"calibrate", "--images", DataDir() + "/images", "--target",
                                       TargetFile(), "--robot", DataDir() + "/RobotPosesVec.txt",
                                       "--setup", "eye-in-hand", "--output", Path("result.json")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_THAT(run.out + run.err, ::testing::HasSubstr("not the size its description states"));
  const nlohmann::json result = nlohmann::json::parse(Read("result.json"));
  const nlohmann::json& target = result["target"];
  EXPECT_TRUE(target["mismatch"].get<bool>());
  EXPECT_GT(target["scale"].get<double>(), 0.93);
  EXPECT_LT(target["scale"].get<double>(), 0.98);
  EXPECT_NEAR(target["measured"]["square"].get<double>(), 0.015 * target["scale"].get<double>(),
              1e-12);
  EXPECT_EQ(target["described"]["square"].get<double>(), 0.015);
  const Eigen::Vector3d board_free(0.0336, -0.1027, -0.0762);
  const auto& sigma = result["covariance"]["sigma"]["X"]["translation_in_parent"]["translation"];
  for (int k = 0; k < 3; ++k) {
    const double t = result["X"]["translation"][static_cast<size_t>(k)].get<double>();
    EXPECT_LT(std::abs(t - board_free(k)), 3.0 * sigma[static_cast<size_t>(k)].get<double>())
        << "axis " << k;
  }
  EXPECT_TRUE(result["certificate"]["certified"].get<bool>());
}

// `hecal calibrate --streams --images` (docs/streams.md#images-as-the-camera-stream): the robot as
// a 50 Hz stream that stops for a second at each of the 28 stations, each image stamped in the
// middle of its stop by a sidecar; the offset given (a robot at rest does not show it). X comes
// back within the reference's tolerance; an image without a stamp stops the run naming it.
TEST_F(Kuka2Images, ImagesAsTheCameraStream) {
  const io::PoseTable stations = io::ReadPoseTable(DataDir() + "/RobotPosesVec.txt", {});
  io::PoseTable stream;
  std::string stamps = "image,stamp\n";
  for (size_t i = 0; i < stations.rows.size(); ++i) {
    for (int k = 0; k < 50; ++k) {
      io::PoseRow row;
      row.pose = stations.rows[i].pose;
      row.stamp = static_cast<double>(i) + 0.02 * k;
      stream.rows.push_back(row);
    }
    char name[400];
    std::snprintf(name, sizeof name, "im_%02zu.png,%.3f\n", i + 1, static_cast<double>(i) + 0.5);
    stamps += name;
  }
  io::WritePoseTable(Path("robot.csv"), stream, {});
  Write("stamps.csv", stamps);
  const std::vector<std::string> args = {
      "calibrate",      "--streams",   "--images",      DataDir() + "/images",
      "--target",       TargetFile(),  "--robot",       Path("robot.csv"),
      "--setup",        "eye-in-hand", "--time-offset", "0",
      "--target-scale", "stated",      "--output",      Path("result.json")};
  std::vector<std::string> with_stamps = args;
  with_stamps.insert(with_stamps.end(), {"--stamps", Path("stamps.csv")});
  const cli_test::Outcome run = Hecal(with_stamps);
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json result = nlohmann::json::parse(Read("result.json"));
  ExpectReferenceX(result);
  EXPECT_EQ(result["streams"]["camera_samples"], 28);
  // Without the sidecar the file names must be stamps; im_01 is not.
  const cli_test::Outcome unnamed = Hecal(args);
  EXPECT_EQ(unnamed.code, 2);
  EXPECT_THAT(unnamed.err, ::testing::HasSubstr("im_01: the image's name is not a time stamp"));
  Write("stamps.csv", "image,stamp\nim_01.png,0.5\n");
  const cli_test::Outcome missing = Hecal(with_stamps);
  EXPECT_EQ(missing.code, 2);
  EXPECT_THAT(missing.err, ::testing::HasSubstr("has no stamp for the image im_02"));
}

#endif
}  // namespace
}  // namespace hecal::cli
