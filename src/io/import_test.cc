#include "hecal/io/import.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

const std::string kData = std::string(HECAL_SOURCE_DIR) + "/data/";
const std::string kFixtures = std::string(HECAL_SOURCE_DIR) + "/src/io/testdata/";

TEST(Import, FormatNames) {
  EXPECT_EQ(ImportFormatList(),
            "moveit|easy_handeye|camodocal|ethz|tabb|opencv-yaml|matrix16|visp");
  for (ImportFormat format :
       {ImportFormat::kMoveit, ImportFormat::kEasyHandeye, ImportFormat::kCamodocal,
        ImportFormat::kEthz, ImportFormat::kTabb, ImportFormat::kOpenCvYaml,
        ImportFormat::kMatrix16, ImportFormat::kVisp}) {
    EXPECT_EQ(ParseImportFormat(ImportFormatName(format)), format);
  }
  EXPECT_FALSE(ParseImportFormat("opencv").has_value());
  EXPECT_FALSE(ParseImportFormat("MoveIt").has_value());
}

std::string ImportErrorOf(ImportFormat format, const std::vector<std::string>& inputs,
                          const ImportOptions& options = {}) {
  try {
    ImportFiles(format, inputs, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Import, TabbFromTheDirectoryOrTheTwoFiles) {
  const std::string dir = kData + "tabb-rwhe-dataset1";
  const ImportedPoses from_dir = ImportFiles(ImportFormat::kTabb, {dir}, {});
  const ImportedPoses from_files =
      ImportFiles(ImportFormat::kTabb, {dir + "/robot_cali.txt", dir + "/cali.txt"}, {});
  ASSERT_EQ(from_dir.robot.rows.size(), 88u);
  EXPECT_TRUE(from_dir.robot.rows[5].pose.isApprox(from_files.robot.rows[5].pose, 1e-15));
  EXPECT_THAT(ImportErrorOf(ImportFormat::kTabb, {dir + "/cali.txt"}), HasSubstr("tabb takes"));
  EXPECT_THAT(ImportErrorOf(ImportFormat::kTabb, {kData}), HasSubstr("robot_cali.txt"));
}

TEST(Import, InputCountsAndUnreadableFiles) {
  const std::string json = kData + "moveit-calibration/pose_samples.json";
  EXPECT_THAT(ImportErrorOf(ImportFormat::kMoveit, {}), HasSubstr("INPUT: moveit takes one"));
  EXPECT_THAT(ImportErrorOf(ImportFormat::kMoveit, {json, json}), HasSubstr("got 2 inputs"));
  EXPECT_THAT(ImportErrorOf(ImportFormat::kEthz, {json}), HasSubstr("ethz takes two CSV files"));
  EXPECT_THAT(ImportErrorOf(ImportFormat::kMatrix16, {json, json, json}), HasSubstr("got 3"));
  EXPECT_THAT(ImportErrorOf(ImportFormat::kCamodocal, {kData + "no/such.yml"}),
              HasSubstr("no/such.yml"));
}

TEST(Import, FlagsThatDoNotApplyAreRejected) {
  const std::string json = kData + "moveit-calibration/pose_samples.json";
  ImportOptions units;
  units.units = LengthUnit::kMillimetre;
  EXPECT_THAT(ImportErrorOf(ImportFormat::kMoveit, {json}, units),
              HasSubstr("ImportOptions.units: moveit files fix their own length unit (m)"));
  EXPECT_THAT(ImportErrorOf(ImportFormat::kTabb, {kData + "tabb-rwhe-dataset1"}, units),
              HasSubstr("(mm)"));
  ImportOptions setup;
  setup.setup = ImportSetup::kEyeInHand;
  EXPECT_THAT(ImportErrorOf(ImportFormat::kMoveit, {json}, setup),
              HasSubstr("ImportOptions.setup: "));
  ImportOptions camera_inverse;
  camera_inverse.camera_inverse = true;
  EXPECT_THAT(ImportErrorOf(ImportFormat::kMatrix16, {kData + "rwhe-kuka2/RobotPosesVec.txt"},
                            camera_inverse),
              HasSubstr("ImportOptions.camera_inverse: given without a camera matrix file"));
}

// --robot-inverse / --camera-inverse apply to every format, after its own convention: each side
// comes out as the exact inverse of the plain import, with a header line saying so.
TEST(Import, InverseFlagsApplyToEveryFormat) {
  const std::string ethz = kData + "ethz-robot-arm/robot_arm_complete_bag_color_and_ir_";
  const std::string tabb = kData + "tabb-rwhe-dataset1";
  const std::string kuka = kData + "rwhe-kuka2/RobotPosesVec.txt";
  const std::pair<ImportFormat, std::vector<std::string>> sources[] = {
      {ImportFormat::kMoveit, {kData + "moveit-calibration/pose_samples.json"}},
      {ImportFormat::kEasyHandeye, {kFixtures + "easy_handeye_eye_on_base.samples"}},
      {ImportFormat::kCamodocal, {kData + "camodocal-artag/TransformPairsInput.yml"}},
      {ImportFormat::kEthz, {ethz + "base_link_sr300_hinge.csv", ethz + "target_ir.csv"}},
      {ImportFormat::kTabb, {tabb}},
      {ImportFormat::kOpenCvYaml, {kFixtures + "opencv_handeye_moveit.yml"}},
      {ImportFormat::kMatrix16, {kuka, kuka}},  // the robot file as a camera file too
      {ImportFormat::kVisp, {kFixtures + "visp"}},
  };
  for (const auto& [format, inputs] : sources) {
    SCOPED_TRACE(std::string(ImportFormatName(format)));
    const ImportedPoses plain = ImportFiles(format, inputs, {});
    ImportOptions both;
    both.robot_inverse = true;
    both.camera_inverse = true;
    const ImportedPoses inverted = ImportFiles(format, inputs, both);
    ASSERT_EQ(inverted.robot.rows.size(), plain.robot.rows.size());
    ASSERT_EQ(inverted.camera->rows.size(), plain.camera->rows.size());
    for (size_t i = 0; i < plain.robot.rows.size(); ++i) {
      EXPECT_TRUE((inverted.robot.rows[i].pose * plain.robot.rows[i].pose)
                      .isApprox(Pose::Identity(), 1e-12));
    }
    for (size_t i = 0; i < plain.camera->rows.size(); ++i) {
      EXPECT_TRUE((inverted.camera->rows[i].pose * plain.camera->rows[i].pose)
                      .isApprox(Pose::Identity(), 1e-12));
    }
    EXPECT_EQ(inverted.robot_notes.size(), plain.robot_notes.size() + 1);
    EXPECT_THAT(inverted.robot_notes.back(), HasSubstr("--robot-inverse"));
    EXPECT_THAT(inverted.robot_notes.back(), HasSubstr("INVERTED to T_base_gripper"));
    EXPECT_THAT(inverted.camera_notes.back(), HasSubstr("INVERTED to T_camera_target"));
  }
  // Only one side: the other is untouched.
  ImportOptions robot_only;
  robot_only.robot_inverse = true;
  const std::vector<std::string> moveit = {kData + "moveit-calibration/pose_samples.json"};
  const ImportedPoses plain = ImportFiles(ImportFormat::kMoveit, moveit, {});
  const ImportedPoses inverted = ImportFiles(ImportFormat::kMoveit, moveit, robot_only);
  EXPECT_TRUE(inverted.camera->rows[7].pose.isApprox(plain.camera->rows[7].pose, 0.0));
  EXPECT_EQ(inverted.camera_notes, plain.camera_notes);
  // The kuka2 flange read as T_gripper_base lands more than 1 m from where it is.
  const std::vector<std::string> kuka_only = {kData + "rwhe-kuka2/RobotPosesVec.txt"};
  EXPECT_GT((ImportFiles(ImportFormat::kMatrix16, kuka_only, robot_only)
                 .robot.rows[0]
                 .pose.translation() -
             ImportFiles(ImportFormat::kMatrix16, kuka_only, {}).robot.rows[0].pose.translation())
                .norm(),
            1.0);
}

TEST(Import, EveryRealDataSetImports) {
  const std::string ethz = kData + "ethz-robot-arm/robot_arm_complete_bag_color_and_ir_";
  EXPECT_EQ(ImportFiles(ImportFormat::kMoveit, {kData + "moveit-calibration/pose_samples.json"}, {})
                .camera->rows.size(),
            50u);
  EXPECT_EQ(
      ImportFiles(ImportFormat::kCamodocal, {kData + "camodocal-artag/TransformPairsInput.yml"}, {})
          .robot.rows.size(),
      42u);
  EXPECT_EQ(ImportFiles(ImportFormat::kEthz,
                        {ethz + "base_link_sr300_hinge.csv", ethz + "target_ir.csv"}, {})
                .camera->rows.size(),
            1703u);
  EXPECT_EQ(ImportFiles(ImportFormat::kMatrix16, {kData + "rwhe-kuka2/RobotPosesVec.txt"}, {})
                .robot.rows.size(),
            28u);
}

// ImportOptions::IsValid for a format: the defaults apply to every format; --units only where the
// files do not fix the unit, --setup only for easy_handeye; the field is named first.
TEST(ImportOptions, IsValidNamesTheFieldForTheFormat) {
  const auto refused = [](ImportFormat format, const ImportOptions& options) {
    std::string why;
    return options.IsValid(format, &why) ? std::string() : why;
  };
  for (const ImportFormat format :
       {ImportFormat::kMoveit, ImportFormat::kEasyHandeye, ImportFormat::kTabb,
        ImportFormat::kMatrix16, ImportFormat::kOpenCvYaml, ImportFormat::kVisp}) {
    EXPECT_EQ(refused(format, {}), "") << ImportFormatName(format);
  }
  ImportOptions units;
  units.units = LengthUnit::kMillimetre;
  EXPECT_EQ(refused(ImportFormat::kMatrix16, units), "");
  EXPECT_EQ(refused(ImportFormat::kOpenCvYaml, units), "");
  EXPECT_EQ(refused(ImportFormat::kTabb, units).rfind("ImportOptions.units: tabb files fix", 0), 0u)
      << refused(ImportFormat::kTabb, units);
  ImportOptions setup;
  setup.setup = ImportSetup::kEyeToHand;
  EXPECT_EQ(refused(ImportFormat::kEasyHandeye, setup), "");
  EXPECT_EQ(refused(ImportFormat::kMoveit, setup).rfind("ImportOptions.setup: ", 0), 0u);
  // ImportFiles refuses them before reading (the input does not exist).
  try {
    ImportFiles(ImportFormat::kMoveit, {"no-such-file.json"}, setup);
    ADD_FAILURE() << "accepted --setup for moveit";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "ImportOptions.setup");
    EXPECT_FALSE(error.fix().empty());
  }
}

}  // namespace
}  // namespace hecal::io
