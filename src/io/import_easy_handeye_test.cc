#include "hecal/io/import_easy_handeye.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/import_moveit.h"
#include "hecal/io/import_tabb.h"
#include "io_test_util.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

// Hand-made fixtures in easy_handeye2's samples layout, with values from the real data sets
// (src/io/testdata/README.md): moveit samples 0-9 (eye_on_base) and Tabb poses 0-9 (eye_in_hand).
const std::string kEyeOnBase =
    test_util::kSource + "/src/io/testdata/easy_handeye_eye_on_base.samples";
const std::string kEyeInHand =
    test_util::kSource + "/src/io/testdata/easy_handeye_eye_in_hand.samples";

void ExpectSamePoses(const PoseTable& actual, const PoseTable& expected, size_t count,
                     double tolerance) {
  ASSERT_EQ(actual.rows.size(), count);
  for (size_t i = 0; i < count; ++i) {
    EXPECT_TRUE(actual.rows[i].pose.isApprox(expected.rows[i].pose, tolerance))
        << "row " << i << "\n"
        << actual.rows[i].pose.matrix() << "\nexpected\n"
        << expected.rows[i].pose.matrix();
  }
}

TEST(ImportEasyHandeye, EyeOnBaseInvertsTheRobotTransform) {
  // easy_handeye samples eye_on_base robots as lookup_transform(effector, base) = T_effector_base;
  // imported, they must equal MoveIt's T_base_eef for the same samples, and so keep the MoveIt
  // data set's consistency (import_moveit_test.cc).
  const ImportedPoses poses = ParseEasyHandeyeSamples(ReadFile(kEyeOnBase), kEyeOnBase, {});
  const std::string moveit_path = test_util::kSource + "/data/moveit-calibration/pose_samples.json";
  const ImportedPoses moveit = ParseMoveitSamples(ReadFile(moveit_path), moveit_path);
  ExpectSamePoses(poses.robot, moveit.robot, 10, 1e-12);
  ExpectSamePoses(*poses.camera, *moveit.camera, 10, 1e-12);
  EXPECT_EQ(poses.robot.rows[3].id, "3");
  EXPECT_THAT(poses.robot_notes[0], HasSubstr("eye_on_base (from the file)"));
  EXPECT_THAT(poses.robot_notes[3], HasSubstr("lookup_transform(tool0, base_link)"));
  EXPECT_THAT(poses.robot_notes[3], HasSubstr("INVERTED"));
  // Read as eye-in-hand (no inverse) the robot poses would be the inverses.
  EXPECT_FALSE(poses.robot.rows[0].pose.isApprox(moveit.robot.rows[0].pose.inverse(), 1e-3));
}

TEST(ImportEasyHandeye, EyeInHandKeepsTheRobotTransform) {
  const ImportedPoses poses = ParseEasyHandeyeSamples(ReadFile(kEyeInHand), kEyeInHand, {});
  const std::string dir = test_util::kSource + "/data/tabb-rwhe-dataset1/";
  const ImportedPoses tabb = ParseTabb(ReadFile(dir + "robot_cali.txt"), "robot_cali.txt",
                                       ReadFile(dir + "cali.txt"), "cali.txt");
  // Same poses (the fixture holds them in metres with exact rotations).
  ExpectSamePoses(poses.robot, tabb.robot, 10, 1e-9);
  ExpectSamePoses(*poses.camera, *tabb.camera, 10, 1e-9);
  EXPECT_EQ(poses.robot.unit, LengthUnit::kMetre);
}

std::string Transform(const std::string& indent, double x, double qw) {
  return indent + "translation: {x: " + std::to_string(x) + ", y: 0, z: 0}\n" + indent +
         "rotation: {x: 0, y: 0, z: 0, w: " + std::to_string(qw) + "}\n";
}

std::string Samples(const std::string& type) {
  return "parameters:\n  calibration_type: '" + type +
         "'\n  robot_base_frame: base\nsamples:\n"
         "- robot:\n" +
         Transform("    ", 0.5, 1) + "  tracking:\n" + Transform("    ", 2, 1);
}

TEST(ImportEasyHandeye, SetupFromTheFileOrTheFlag) {
  EXPECT_DOUBLE_EQ(ParseEasyHandeyeSamples(Samples("eye_in_hand"), "s.yaml", {})
                       .robot.rows[0]
                       .pose.translation()
                       .x(),
                   0.5);
  EXPECT_DOUBLE_EQ(ParseEasyHandeyeSamples(Samples("eye_on_base"), "s.yaml", {})
                       .robot.rows[0]
                       .pose.translation()
                       .x(),
                   -0.5);
  // Empty calibration_type (as in easy_handeye2's own test data): --setup decides.
  EXPECT_DOUBLE_EQ(ParseEasyHandeyeSamples(Samples(""), "s.yaml", ImportSetup::kEyeToHand)
                       .robot.rows[0]
                       .pose.translation()
                       .x(),
                   -0.5);
  EXPECT_THAT(
      ParseEasyHandeyeSamples(Samples(""), "s.yaml", ImportSetup::kEyeInHand).robot_notes[0],
      HasSubstr("from --setup"));
  try {
    ParseEasyHandeyeSamples(Samples(""), "s.yaml", {});
    ADD_FAILURE() << "no error without a setup";
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("pass --setup eye-in-hand"));
  }
  try {
    ParseEasyHandeyeSamples(Samples("eye_in_hand"), "s.yaml", ImportSetup::kEyeToHand);
    ADD_FAILURE() << "no error for a contradicting --setup";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "ImportOptions.setup");
    EXPECT_THAT(std::string(e.what()), HasSubstr("s.yaml:2, which says eye_in_hand"));
  }
}

TEST(ImportEasyHandeye, Ros1Variants) {
  // ROS 1: eye_on_hand flag, "optical" key, TransformStamped with stamps.
  const std::string stamped =
      "parameters: {eye_on_hand: false}\n"
      "samples:\n"
      "- robot:\n"
      "    header: {stamp: {secs: 10, nsecs: 500000000}}\n"
      "    transform:\n" +
      Transform("      ", 0.5, 1) +
      "  optical:\n"
      "    header: {stamp: {secs: 10, nsecs: 600000000}}\n"
      "    transform:\n" +
      Transform("      ", 2, 1);
  const ImportedPoses poses = ParseEasyHandeyeSamples(stamped, "s.yaml", {});
  EXPECT_DOUBLE_EQ(poses.robot.rows[0].pose.translation().x(), -0.5);
  EXPECT_DOUBLE_EQ(*poses.robot.rows[0].stamp, 10.5);
  EXPECT_DOUBLE_EQ(*poses.camera->rows[0].stamp, 10.6);
  // The SampleList message: two lists.
  const std::string lists = "hand_world_samples:\n- " + Transform("  ", 0.5, 1).substr(2) +
                            "camera_marker_samples:\n- " + Transform("  ", 2, 1).substr(2);
  const ImportedPoses two = ParseEasyHandeyeSamples(lists, "s.yaml", ImportSetup::kEyeInHand);
  EXPECT_DOUBLE_EQ(two.robot.rows[0].pose.translation().x(), 0.5);
  EXPECT_DOUBLE_EQ(two.camera->rows[0].pose.translation().x(), 2.0);
  EXPECT_FALSE(two.robot.rows[0].stamp.has_value());
}

void ExpectEasyHandeyeError(const std::string& text, const std::string& part) {
  try {
    ParseEasyHandeyeSamples(text, "s.yaml", ImportSetup::kEyeInHand);
    ADD_FAILURE() << "no error; expected " << part;
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr(part)) << text;
  }
}

TEST(ImportEasyHandeye, RejectsBadInput) {
  ExpectEasyHandeyeError("", "not a YAML map");
  ExpectEasyHandeyeError("samples: [", "not valid YAML");
  ExpectEasyHandeyeError("foo: 1\n", "no samples");
  ExpectEasyHandeyeError("parameters: {}\ntransformation: {x: 1}\n", "calibration result");
  ExpectEasyHandeyeError("samples: []\n", "empty");
  ExpectEasyHandeyeError("samples: 5\n", "samples is not a list");
  ExpectEasyHandeyeError("samples:\n- robot: {}\n", "lacks tracking");
  ExpectEasyHandeyeError("samples:\n- robot: {}\n  tracking: {}\n",
                         "s.yaml:2: sample 0 robot is not a");
  const std::string good = Transform("    ", 0.5, 1);
  ExpectEasyHandeyeError("samples:\n- robot:\n" + good + "  tracking:\n" + Transform("    ", 2, 0),
                         "zero quaternion");
  ExpectEasyHandeyeError(
      "samples:\n- robot:\n" + good + "  tracking:\n" + Transform("    ", 2, 1.5), "norm 1.5");
  std::string nan = "samples:\n- robot:\n" + good + "  tracking:\n" + good;
  nan.replace(nan.find("0.500000"), 8, ".nan");
  ExpectEasyHandeyeError(nan, "non-finite");
  std::string text = "samples:\n- robot:\n" + good + "  tracking:\n" + good;
  text.replace(text.find("0.500000"), 8, "zero");
  ExpectEasyHandeyeError(text, "s.yaml:3: sample 0 robot translation x is \"zero\", not a number");
  ExpectEasyHandeyeError("parameters: {calibration_type: sideways}\nsamples:\n- robot:\n" + good +
                             "  tracking:\n" + good,
                         "not eye_in_hand or eye_on_base");
  ExpectEasyHandeyeError(
      "parameters: {eye_on_hand: maybe}\nsamples:\n- robot:\n" + good + "  tracking:\n" + good,
      "not true or false");
  ExpectEasyHandeyeError("hand_world_samples: []\ncamera_marker_samples:\n- {}\n",
                         "hand_world_samples has 0 transforms but camera_marker_samples has 1");
}

}  // namespace
}  // namespace hecal::io
