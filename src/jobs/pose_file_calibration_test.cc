// CalibrateFromPoseFiles on pose tables written from a synthetic scene with known X and Z
// (testing/scene.h, Z = A_i X B_i, handeye/problem.h): X and Z recovered, the setup picked when
// none is given, an inverted camera table stopped with the fix in the caller's words and
// calibrated once inverted on reading, one file given twice (or a copy of its poses) refused in
// the caller's words, `all_methods` giving every method of estimation::AllMethods(), and invalid
// options refused naming the field before any file is read.
#include "hecal/jobs/pose_file_calibration.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/estimation/methods.h"
#include "hecal/geometry/so3.h"
#include "testing/pose_csv.h"
#include "testing/scene.h"
#include "testing/scratch_folder.h"
#include "testing/thrown.h"

namespace hecal::jobs {
namespace {

using ::testing::HasSubstr;

class PoseFileCalibrationTest : public testing::ScratchFolderTest {
 protected:
  PoseFileCalibrationTest() : ScratchFolderTest("hecal_pose_file_job") {}

  void SetUp() override {
    ScratchFolderTest::SetUp();
    WriteScene(handeye::Setup::kEyeInHand);
  }

  // A scene of 12 stations, 0.1 mrad / 0.1 mm of noise, written in millimetres; `camera` the
  // camera table's poses (default: the scene's T_camera_target).
  void WriteScene(handeye::Setup setup) {
    std::mt19937_64 rng(11);
    scene_ = testing::MakeScene(
        {.setup = setup, .stations = 12, .robot_noise = {1e-4, 1e-4}, .camera_noise = {1e-4, 1e-4}},
        rng);
    options_.robot = Write("robot.csv", testing::PoseCsv(scene_.T_base_gripper, 1e3, "_mm"));
    options_.camera = Write("camera.csv", testing::PoseCsv(scene_.T_camera_target, 1e3, "_mm"));
    options_.setup = setup;
  }

  void ExpectTruth(const estimation::CalibrationResult& result) const {
    EXPECT_LT(so3::Log(result.X.linear().transpose() * scene_.X.linear()).norm(), 1e-3);
    EXPECT_LT((result.X.translation() - scene_.X.translation()).norm(), 1e-3);  // metres
    EXPECT_LT(so3::Log(result.Z.linear().transpose() * scene_.Z.linear()).norm(), 1e-3);
    EXPECT_LT((result.Z.translation() - scene_.Z.translation()).norm(), 1e-3);
  }

  testing::Scene scene_;
  PoseFileCalibrationOptions options_;
};

TEST_F(PoseFileCalibrationTest, RecoversTheKnownHandEye) {
  const report::ResultDocument document = CalibrateFromPoseFiles(options_).document;
  ASSERT_EQ(document.results.size(), 1u);
  EXPECT_EQ(document.results[0].method, options_.calibrate.method);
  EXPECT_EQ(document.setup, handeye::Setup::kEyeInHand);
  EXPECT_EQ(document.unit, io::LengthUnit::kMillimetre);  // the robot table's
  ASSERT_EQ(document.station_ids.size(), 12u);
  EXPECT_EQ(document.station_ids.front(), "s0");
  ExpectTruth(document.results[0]);
}

TEST_F(PoseFileCalibrationTest, PicksTheSetupTheDataFit) {
  options_.setup.reset();
  const report::ResultDocument document = CalibrateFromPoseFiles(options_).document;
  EXPECT_EQ(document.setup, handeye::Setup::kEyeInHand);
  ASSERT_EQ(document.results.size(), 1u);
  ExpectTruth(document.results[0]);
}

// T_target_camera in the camera table of an eye-to-hand rig: stopped, with the camera table
// inverted as the fix in the caller's words (poses alone cannot tell it from the other setup, so
// the source is the setup, and the fix names both); inverting on reading calibrates.
TEST_F(PoseFileCalibrationTest, InvertedCameraTableIsStoppedWithItsFix) {
  WriteScene(handeye::Setup::kEyeToHand);
  std::vector<Pose> inverted;
  for (const Pose& pose : scene_.T_camera_target) inverted.push_back(pose.inverse());
  options_.camera = Write("camera.csv", testing::PoseCsv(inverted, 1e3, "_mm"));
  options_.words.invert_camera = "add the camera switch";
  const InputError error = testing::Thrown<InputError>([&] { CalibrateFromPoseFiles(options_); });
  EXPECT_EQ(error.source(), "ConventionCheckOptions.setup");
  EXPECT_THAT(error.problem(), HasSubstr("with the camera poses inverted (T_target_camera)"));
  EXPECT_THAT(error.fix(), HasSubstr("if it is fixed, add the camera switch")) << error.what();

  options_.camera_read.invert = true;
  const report::ResultDocument document = CalibrateFromPoseFiles(options_).document;
  ASSERT_EQ(document.results.size(), 1u);
  ExpectTruth(document.results[0]);
}

TEST_F(PoseFileCalibrationTest, SameFileTwiceIsRefusedInTheCallersWords) {
  options_.camera = options_.robot;
  options_.file_words = {"--robot", "--camera"};
  const InputError same_file =
      testing::Thrown<InputError>([&] { CalibrateFromPoseFiles(options_); });
  EXPECT_EQ(same_file.source(), options_.robot);
  EXPECT_EQ(same_file.problem(), "is the same file as --robot " + options_.robot);
  EXPECT_EQ(same_file.fix(),
            "give the robot poses (T_base_gripper, from the controller) with --robot and the "
            "camera poses (T_camera_target, from PnP or hecal detect) with --camera");

  // A copy of the robot poses, inverted: the same poses in another file.
  std::vector<Pose> inverted;
  for (const Pose& pose : scene_.T_base_gripper) inverted.push_back(pose.inverse());
  options_.camera = Write("copy.csv", testing::PoseCsv(inverted, 1e3, "_mm"));
  options_.file_words = {};
  const InputError same_poses =
      testing::Thrown<InputError>([&] { CalibrateFromPoseFiles(options_); });
  EXPECT_EQ(same_poses.source(), options_.camera);
  EXPECT_EQ(same_poses.problem(),
            "holds the same poses as the robot table " + options_.robot + " (or their inverses)");
  EXPECT_THAT(same_poses.fix(), HasSubstr("with the robot table and"));
}

// Every method once: a result or a failure with its reason; the solvers agree with the truth.
TEST_F(PoseFileCalibrationTest, AllMethodsGivesEveryMethod) {
  options_.all_methods = true;
  const report::ResultDocument document = CalibrateFromPoseFiles(options_).document;
  EXPECT_TRUE(document.all_methods);
  std::set<estimation::Method> seen;
  for (const estimation::CalibrationResult& result : document.results) {
    EXPECT_TRUE(seen.insert(result.method).second);
    ExpectTruth(result);
  }
  for (const report::MethodFailure& failure : document.failures) {
    EXPECT_TRUE(seen.insert(failure.method).second);
    EXPECT_FALSE(failure.message.empty());
  }
  EXPECT_EQ(seen.size(), estimation::AllMethods().size());
  EXPECT_GE(document.results.size(), estimation::AllMethods().size() - 1);
}

// Refused naming the field, before any file is read (the tables named below do not exist).
TEST_F(PoseFileCalibrationTest, InvalidOptionsNameTheField) {
  const auto refused = [](const PoseFileCalibrationOptions& options, const std::string& field) {
    std::string why;
    EXPECT_FALSE(options.IsValid(&why));
    EXPECT_EQ(why.rfind(field + ": ", 0), 0u) << why;
    const InputError error = testing::Thrown<InputError>([&] { CalibrateFromPoseFiles(options); });
    EXPECT_EQ(error.source(), field) << error.what();
  };
  PoseFileCalibrationOptions options;
  options.robot = "missing-robot.csv";
  options.camera = "missing-camera.csv";
  EXPECT_TRUE(options.IsValid(nullptr));

  PoseFileCalibrationOptions no_robot = options;
  no_robot.robot.clear();
  refused(no_robot, "PoseFileCalibrationOptions.robot");
  PoseFileCalibrationOptions no_camera = options;
  no_camera.camera.clear();
  refused(no_camera, "PoseFileCalibrationOptions.camera");
  PoseFileCalibrationOptions samples = options;
  samples.calibrate.covariance.samples = 1;
  refused(samples, "CovarianceOptions.samples");
  PoseFileCalibrationOptions units = options;
  units.camera_read.units = static_cast<io::LengthUnit>(7);
  refused(units, "PoseReadOptions.units");
}

}  // namespace
}  // namespace hecal::jobs
