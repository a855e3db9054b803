#include "hecal/io/import.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "hecal/core/error.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

const std::string kData = std::string(HECAL_SOURCE_DIR) + "/data/";

TEST(Import, FormatNames) {
  EXPECT_EQ(ImportFormatList(), "moveit|easy_handeye|camodocal|ethz|tabb|opencv-yaml|matrix16");
  for (ImportFormat format : {ImportFormat::kMoveit, ImportFormat::kEasyHandeye,
                              ImportFormat::kCamodocal, ImportFormat::kEthz, ImportFormat::kTabb,
                              ImportFormat::kOpenCvYaml, ImportFormat::kMatrix16}) {
    EXPECT_EQ(ParseImportFormat(ImportFormatName(format)), format);
  }
  EXPECT_FALSE(ParseImportFormat("opencv").has_value());
  EXPECT_FALSE(ParseImportFormat("MoveIt").has_value());
}

std::string ErrorOf(ImportFormat format, const std::vector<std::string>& inputs,
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
  EXPECT_THAT(ErrorOf(ImportFormat::kTabb, {dir + "/cali.txt"}), HasSubstr("tabb takes"));
  EXPECT_THAT(ErrorOf(ImportFormat::kTabb, {kData}), HasSubstr("robot_cali.txt"));
}

TEST(Import, InputCountsAndUnreadableFiles) {
  const std::string json = kData + "moveit-calibration/pose_samples.json";
  EXPECT_THAT(ErrorOf(ImportFormat::kMoveit, {}), HasSubstr("INPUT: moveit takes one"));
  EXPECT_THAT(ErrorOf(ImportFormat::kMoveit, {json, json}), HasSubstr("got 2 inputs"));
  EXPECT_THAT(ErrorOf(ImportFormat::kEthz, {json}), HasSubstr("ethz takes two CSV files"));
  EXPECT_THAT(ErrorOf(ImportFormat::kMatrix16, {json, json, json}), HasSubstr("got 3"));
  EXPECT_THAT(ErrorOf(ImportFormat::kCamodocal, {kData + "no/such.yml"}), HasSubstr("no/such.yml"));
}

TEST(Import, FlagsThatDoNotApplyAreRejected) {
  const std::string json = kData + "moveit-calibration/pose_samples.json";
  ImportOptions units;
  units.units = LengthUnit::kMillimetre;
  EXPECT_THAT(ErrorOf(ImportFormat::kMoveit, {json}, units),
              HasSubstr("--units: moveit files fix their own length unit (m)"));
  EXPECT_THAT(ErrorOf(ImportFormat::kTabb, {kData + "tabb-rwhe-dataset1"}, units),
              HasSubstr("(mm)"));
  ImportOptions setup;
  setup.setup = ImportSetup::kEyeInHand;
  EXPECT_THAT(ErrorOf(ImportFormat::kMoveit, {json}, setup), HasSubstr("--setup"));
  ImportOptions inverse;
  inverse.robot_inverse = true;
  EXPECT_THAT(ErrorOf(ImportFormat::kCamodocal, {json}, inverse), HasSubstr("--robot-inverse"));
  ImportOptions camera_inverse;
  camera_inverse.camera_inverse = true;
  EXPECT_THAT(
      ErrorOf(ImportFormat::kMatrix16, {kData + "rwhe-kuka2/RobotPosesVec.txt"}, camera_inverse),
      HasSubstr("--camera-inverse: given without a camera matrix file"));
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

}  // namespace
}  // namespace hecal::io
