// CalibrateFromPoses and CalibratePoses (pose_calibration.h) on exact synthetic stations
// (Z = A_i X B_i built from a chosen X and Z): one method recovers them; every method is accounted
// for as a result or a failure; the caller's notes come first in every result's warnings; a
// non-finite result is refused. CalibratePoses: lists in millimetres, the setup picked, and each
// malformed list refused with its name and the index of the bad pose.
#include "hecal/jobs/pose_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/estimation/methods.h"
#include "testing/random_poses.h"

namespace hecal::jobs {
namespace {

// Eye-in-hand stations with T_base_gripper_i · X · T_camera_target_i = Z exactly.
PoseCalibrationInput ExactInput(const Pose& X, const Pose& Z, int stations) {
  std::mt19937_64 rng(11);
  std::vector<Pose> robot, camera;
  for (int i = 0; i < stations; ++i) {
    const Pose A = testing::RandomPose(rng, 0.5);
    robot.push_back(A);
    camera.push_back((A * X).inverse() * Z);
  }
  PoseCalibrationInput input;
  input.problem = handeye::MakeProblem(handeye::Setup::kEyeInHand, robot, camera);
  for (int i = 0; i < stations; ++i) input.station_ids.push_back(std::to_string(i + 1));
  input.plausibility = {handeye::Setup::kEyeInHand, robot, camera, true, true};
  input.notes = {"a note from the caller"};
  return input;
}

TEST(CalibrateFromPosesTest, OneMethodRecoversXAndZ) {
  std::mt19937_64 rng(5);
  const Pose X = testing::RandomPose(rng, 0.1);
  const Pose Z = testing::RandomPose(rng, 1.0);
  estimation::CalibrateOptions options;
  options.method = estimation::Method::kTsaiLenz;
  const report::ResultDocument document = CalibrateFromPoses(ExactInput(X, Z, 8), options, false);
  ASSERT_EQ(document.results.size(), 1u);
  EXPECT_FALSE(document.all_methods);
  EXPECT_EQ(document.station_ids.size(), 8u);
  EXPECT_TRUE(document.rejected.empty());
  const estimation::CalibrationResult& result = document.results[0];
  EXPECT_TRUE(result.X.isApprox(X, 1e-6));
  EXPECT_TRUE(result.Z.isApprox(Z, 1e-6));
  ASSERT_FALSE(result.warnings.empty());
  EXPECT_EQ(result.warnings[0], "a note from the caller");
}

TEST(CalibrateFromPosesTest, EveryMethodIsAResultOrAFailure) {
  std::mt19937_64 rng(6);
  const Pose X = testing::RandomPose(rng, 0.1);
  const Pose Z = testing::RandomPose(rng, 1.0);
  const report::ResultDocument document = CalibrateFromPoses(ExactInput(X, Z, 8), {}, true);
  EXPECT_TRUE(document.all_methods);
  EXPECT_EQ(document.results.size() + document.failures.size(), estimation::AllMethods().size());
  for (const estimation::CalibrationResult& result : document.results) {
    EXPECT_TRUE(result.X.isApprox(X, 1e-4)) << estimation::Info(result.method).name;
    EXPECT_EQ(result.warnings.at(0), "a note from the caller");
  }
}

TEST(CheckFiniteResultTest, RefusesANonFiniteSolution) {
  estimation::CalibrationResult result;
  EXPECT_NO_THROW(CheckFiniteResult(result));
  result.translation_rms = std::numeric_limits<double>::infinity();
  EXPECT_THROW(CheckFiniteResult(result), DegenerateError);
}

// Eye-in-hand lists with T_base_gripper_i · X · T_camera_target_i = Z, lengths times `scale`.
struct Lists {
  std::vector<Pose> robot, camera;
};
Lists ExactLists(const Pose& X, const Pose& Z, int stations, double scale) {
  std::mt19937_64 rng(12);
  Lists lists;
  for (int i = 0; i < stations; ++i) {
    const Pose A = testing::RandomPose(rng, 0.5);
    Pose B = (A * X).inverse() * Z;
    Pose A_scaled = A;
    A_scaled.translation() *= scale;
    B.translation() *= scale;
    lists.robot.push_back(A_scaled);
    lists.camera.push_back(B);
  }
  return lists;
}

class CalibratePosesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::mt19937_64 rng(7);
    X_ = testing::RandomPose(rng, 0.1);
    Z_ = testing::RandomPose(rng, 1.0);
  }
  // The message of the InputError CalibratePoses throws, with its source checked.
  static std::string Refusal(const Lists& lists, const PoseCalibrationOptions& options,
                             const std::string& source) {
    try {
      CalibratePoses(lists.robot, lists.camera, options);
    } catch (const InputError& error) {
      EXPECT_EQ(error.source(), source) << error.what();
      return error.what();
    }
    ADD_FAILURE() << "no InputError";
    return "";
  }
  Pose X_, Z_;
};

TEST_F(CalibratePosesTest, RecoversXAndZFromListsInMillimetres) {
  PoseCalibrationOptions options;
  options.setup = handeye::Setup::kEyeInHand;
  options.robot_unit = io::LengthUnit::kMillimetre;
  options.camera_unit = io::LengthUnit::kMillimetre;
  const Lists lists = ExactLists(X_, Z_, 10, 1000.0);
  const report::ResultDocument document =
      CalibratePoses(lists.robot, lists.camera, options).document;
  ASSERT_EQ(document.results.size(), 1u);
  EXPECT_EQ(document.unit, io::LengthUnit::kMillimetre);
  EXPECT_EQ(document.station_ids.front(), "1");
  EXPECT_EQ(document.station_ids.back(), "10");
  EXPECT_TRUE(document.results[0].X.isApprox(X_, 1e-6));  // metres inside
  EXPECT_TRUE(document.results[0].Z.isApprox(Z_, 1e-6));
}

TEST_F(CalibratePosesTest, PicksTheSetupTheListsFit) {
  const Lists lists = ExactLists(X_, Z_, 10, 1.0);
  PoseCalibrationOptions options;
  options.station_ids = {"a", "b", "c", "d", "e", "f", "g", "h", "i", "j"};
  const report::ResultDocument document =
      CalibratePoses(lists.robot, lists.camera, options).document;
  EXPECT_EQ(document.setup, handeye::Setup::kEyeInHand);
  EXPECT_EQ(document.station_ids.front(), "a");
  EXPECT_FALSE(document.results.at(0).warnings.empty());  // the evidence for the setup
}

TEST_F(CalibratePosesTest, InvertedCameraListIsStoppedWithItsFix) {
  Lists lists = ExactLists(X_, Z_, 10, 1.0);
  for (Pose& pose : lists.camera) pose = pose.inverse();
  PoseCalibrationOptions options;
  options.setup = handeye::Setup::kEyeInHand;
  // Inverted camera poses eye-in-hand fit as well as the other setup: both fixes are named.
  const std::string why = Refusal(lists, options, "ConventionCheckOptions.setup");
  EXPECT_NE(why.find("invert the camera poses on reading"), std::string::npos) << why;
  EXPECT_NE(why.find("setup eye-to-hand"), std::string::npos) << why;
}

TEST_F(CalibratePosesTest, MalformedListsAreRefusedNamingListAndIndex) {
  PoseCalibrationOptions options;
  options.setup = handeye::Setup::kEyeInHand;
  Lists lists = ExactLists(X_, Z_, 6, 1.0);
  lists.camera.pop_back();
  EXPECT_NE(
      Refusal(lists, options, "T_camera_target").find("has 5 poses where T_base_gripper has 6"),
      std::string::npos);

  lists = ExactLists(X_, Z_, 6, 1.0);
  lists.robot[2].translation().x() = std::nan("");
  EXPECT_NE(Refusal(lists, options, "T_base_gripper").find("pose at index 2 is not finite"),
            std::string::npos);

  lists = ExactLists(X_, Z_, 6, 1.0);
  lists.camera[4].linear() *= 1.01;  // a scaled rotation
  EXPECT_NE(
      Refusal(lists, options, "T_camera_target").find("pose at index 4 has no proper rotation"),
      std::string::npos);

  lists = ExactLists(X_, Z_, 6, 1.0);
  lists.camera[1].linear() = -lists.camera[1].linear();  // a reflection: det -1
  EXPECT_NE(
      Refusal(lists, options, "T_camera_target").find("pose at index 1 has no proper rotation"),
      std::string::npos);

  lists = ExactLists(X_, Z_, 6, 1.0);
  options.station_ids = {"only one"};
  EXPECT_NE(Refusal(lists, options, "PoseCalibrationOptions.station_ids").find("has 1 ids for 6"),
            std::string::npos);
}

TEST_F(CalibratePosesTest, TheSamePosesTwiceAreRefused) {
  Lists lists = ExactLists(X_, Z_, 6, 1.0);
  lists.camera = lists.robot;
  const std::string why = Refusal(lists, {}, "T_camera_target");
  EXPECT_NE(why.find("holds the same poses as the robot list T_base_gripper"), std::string::npos)
      << why;
  for (Pose& pose : lists.camera) pose = pose.inverse();
  EXPECT_NE(Refusal(lists, {}, "T_camera_target").find("or their inverses"), std::string::npos);
}

TEST_F(CalibratePosesTest, InvalidOptionsNameTheField) {
  const Lists lists = ExactLists(X_, Z_, 6, 1.0);
  PoseCalibrationOptions options;
  options.robot_source.clear();
  Refusal(lists, options, "PoseCalibrationOptions.robot_source");
  options = {};
  options.calibrate.robust_scale = -1.0;
  Refusal(lists, options, "CalibrateOptions.robust_scale");
}

}  // namespace
}  // namespace hecal::jobs
