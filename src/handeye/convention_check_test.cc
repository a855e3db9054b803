#include "hecal/handeye/convention_check.h"

#include <gtest/gtest.h>

#include <string>

#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "testing/handeye_cases.h"

namespace hecal::handeye {
namespace {

// Thesis-protocol data of `setup` (20 stations, 0.1 mm / 0.1°), units not named.
PoseData Correct(Setup setup) {
  const testing::Scene scene =
      testing::ThesisCase(setup, 20, 5003, 0.1 * kRadiansPerDegree, 0.1e-3);
  PoseData data;
  data.T_base_gripper = scene.T_base_gripper;
  data.T_camera_target = scene.T_camera_target;
  data.robot_unit_named = data.camera_unit_named = false;
  return data;
}

ConventionCheckOptions Given(std::optional<Setup> setup) {
  ConventionCheckOptions options;
  options.setup = setup;
  options.robot_source = "robot.csv";
  options.camera_source = "camera.csv";
  return options;
}

// The InputError `check` throws (fails the test when it returns).
template <class Check>
InputError Refusal(Check check) {
  try {
    check();
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", 0, "", "");
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ConventionCheck, CorrectDataPassWithTheSetupGiven) {
  for (const handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    const ConventionCheck check = CheckConventions(Correct(setup), Given(setup));
    EXPECT_EQ(check.setup, setup);
    EXPECT_TRUE(check.notes.empty());
  }
}

// No setup given: the one the data were made with is picked, the evidence in the library's words.
TEST(ConventionCheck, PicksTheSetupTheDataWereMadeWith) {
  for (const handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    const ConventionCheck check = CheckConventions(Correct(setup), Given(std::nullopt));
    EXPECT_EQ(check.setup, setup);
    ASSERT_GE(check.notes.size(), 2u);
    EXPECT_EQ(check.notes[0].rfind("setup auto chose " + std::string(SetupName(setup)) + ": ", 0),
              0u)
        << check.notes[0];
    EXPECT_TRUE(Contains(check.notes[1], "with the camera poses inverted")) << check.notes[1];
  }
}

// Robot poses written as T_gripper_base: the robot file is named, the fix inverts it; once the
// caller inverted them already, the fix is not to.
TEST(ConventionCheck, NamesAnInvertedRobotFile) {
  PoseData data = Correct(Setup::kEyeInHand);
  for (Pose& T : data.T_base_gripper) T = T.inverse();
  ConventionCheckOptions options = Given(Setup::kEyeInHand);
  InputError error = Refusal([&] { CheckConventions(data, options); });
  EXPECT_EQ(error.source(), "robot.csv");
  EXPECT_TRUE(Contains(error.problem(),
                       "the robot poses inverted (T_gripper_base) with setup "
                       "eye-in-hand"))
      << error.problem();
  EXPECT_EQ(error.fix().rfind("invert the robot poses on reading (the robot file holds "
                              "T_gripper_base); or, if the camera is fixed, run with setup "
                              "eye-to-hand",
                              0),
            0u)
      << error.fix();
  options.robot_inverted = true;
  error = Refusal([&] { CheckConventions(data, options); });
  EXPECT_EQ(error.fix().rfind("do not invert the robot poses on reading;", 0), 0u) << error.fix();
}

// The other setup is the fix: the source is the setup field, the camera inversion is offered.
TEST(ConventionCheck, NamesTheOtherSetupAsTheSetupField) {
  const InputError error =
      Refusal([&] { CheckConventions(Correct(Setup::kEyeToHand), Given(Setup::kEyeInHand)); });
  EXPECT_EQ(error.source(), "ConventionCheckOptions.setup");
  EXPECT_TRUE(Contains(error.problem(), "these data fit the camera fixed (eye-to-hand)"))
      << error.problem();
  EXPECT_TRUE(Contains(error.fix(),
                       "run with setup eye-to-hand; if it is on the robot, invert "
                       "the camera poses on reading"))
      << error.fix();
}

// Camera millimetres read as metres: the camera file is named with the unit that fits, in the
// caller's words (a command for 12/16-number files only when the caller names one).
TEST(ConventionCheck, NamesTheUnitInTheCallersWords) {
  PoseData data = Correct(Setup::kEyeInHand);
  for (Pose& T : data.T_camera_target) T.translation() *= 1e3;
  ConventionCheckOptions options = Given(Setup::kEyeInHand);
  InputError error = Refusal([&] { CheckConventions(data, options); });
  EXPECT_EQ(error.source(), "camera.csv");
  EXPECT_EQ(error.problem().rfind("the camera lengths fit as millimetres, not metres: ", 0), 0u)
      << error.problem();
  EXPECT_EQ(error.fix(),
            "name the unit in the header of camera.csv (x_mm,y_mm,z_mm), or give "
            "units mm when both files are in mm");
  options.camera_matrix_lines = true;
  error = Refusal([&] { CheckConventions(data, options); });
  EXPECT_EQ(error.fix(),
            "write camera.csv as a pose CSV in mm, or give units mm when both files are in mm");
  options.words.units = "--units";
  options.words.import_matrix_lines = "convert";
  error = Refusal([&] { CheckConventions(data, options); });
  EXPECT_EQ(error.fix(),
            "write camera.csv as a pose CSV in mm (convert camera.csv --units mm "
            "...), or give --units mm when both files are in mm");
}

TEST(ConventionCheck, FewStationsAreLeftToTheSolverUnlessTheSetupIsToBePicked) {
  PoseData data = Correct(Setup::kEyeInHand);
  data.T_base_gripper.resize(2);
  data.T_camera_target.resize(2);
  EXPECT_EQ(CheckConventions(data, Given(Setup::kEyeToHand)).setup, Setup::kEyeToHand);
  const InputError error = Refusal([&] { CheckConventions(data, Given(std::nullopt)); });
  EXPECT_EQ(error.source(), "ConventionCheckOptions.setup");
  EXPECT_EQ(error.problem(),
            "setup auto needs at least 3 stations to tell the setups apart, got 2");
}

TEST(ConventionCheck, RefusesInvalidConsensusOptions) {
  ConventionCheckOptions options = Given(Setup::kEyeInHand);
  options.consensus.max_hypotheses = 0;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  const InputError error = Refusal([&] { CheckConventions(Correct(Setup::kEyeInHand), options); });
  EXPECT_EQ(error.source(), "ConsensusOptions.max_hypotheses");
}

}  // namespace
}  // namespace hecal::handeye
