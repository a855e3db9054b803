// ImportSamples on the bundled Tabb data set (data/tabb-rwhe-dataset1), checked against the poses
// and intrinsics read by the test's own parser (testing/tabb_dataset.h) and the values printed in
// cali.txt; and its options refused field by field before any file is read.
#include "hecal/jobs/import.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "testing/scratch_folder.h"
#include "testing/tabb_dataset.h"
#include "testing/thrown.h"

namespace hecal::jobs {
namespace {

using ::testing::HasSubstr;

const std::string kTabb = std::string(HECAL_SOURCE_DIR) + "/data/tabb-rwhe-dataset1";

ImportJobOptions TabbOptions() {
  ImportJobOptions options;
  options.format = io::ImportFormat::kTabb;
  options.inputs = {kTabb};
  options.robot = "robot.csv";
  options.camera = "camera.csv";
  options.intrinsics = "camera.yaml";
  return options;
}

// The written tables read back equal Tabb's files as the test's parser reads them (robot inverted
// from T_gripper_base, millimetres kept); camera.yaml holds cali.txt's K and distortion.
TEST(ImportJob, TabbTextsMatchTheSourceFiles) {
  const ImportJob job = ImportSamples(TabbOptions());
  const testing::TabbDataset truth = testing::LoadTabbDataset();
  const io::PoseTable robot = io::ParsePoseTable(job.texts.robot, "robot.csv", {});
  ASSERT_TRUE(job.texts.camera.has_value());
  const io::PoseTable camera = io::ParsePoseTable(*job.texts.camera, "camera.csv", {});
  ASSERT_EQ(robot.rows.size(), truth.T_base_gripper.size());
  ASSERT_EQ(camera.rows.size(), truth.T_camera_target.size());
  EXPECT_EQ(robot.unit, io::LengthUnit::kMillimetre);
  for (size_t i = 0; i < robot.rows.size(); ++i) {
    const Pose& G = truth.T_base_gripper[i];
    EXPECT_LT((robot.rows[i].pose.translation() - G.translation()).norm(), 1e-9) << i;
    EXPECT_LT(so3::Log(robot.rows[i].pose.linear().transpose() * G.linear()).norm(), 1e-6) << i;
    const Pose& C = truth.T_camera_target[i];
    EXPECT_LT((camera.rows[i].pose.translation() - C.translation()).norm(), 1e-9) << i;
    EXPECT_LT(so3::Log(camera.rows[i].pose.linear().transpose() * C.linear()).norm(), 1e-6) << i;
  }
  ASSERT_TRUE(job.texts.intrinsics.has_value());
  EXPECT_THAT(*job.texts.intrinsics, HasSubstr("fx: 1081.59\nfy: 1083.49\ncx: 317.249\n"));
  EXPECT_THAT(job.texts.robot, HasSubstr("import --format tabb"));
  EXPECT_EQ(job.imported.sources.size(), 2u);
}

// Each option the format cannot fill is refused naming its field, before the inputs are read
// (they do not exist here).
TEST(ImportJob, RefusesOptionsByField) {
  auto field_of = [](const ImportJobOptions& options) {
    return testing::Thrown<InputError>([&] { ImportSamples(options); }).source();
  };
  ImportJobOptions options = TabbOptions();
  options.inputs = {"no/such/folder"};
  options.robot.clear();
  EXPECT_EQ(field_of(options), "ImportJobOptions.robot");

  options = TabbOptions();
  options.format = io::ImportFormat::kMoveit;
  options.inputs = {"no/such.json"};
  options.intrinsics.clear();
  options.camera.clear();
  EXPECT_EQ(field_of(options), "ImportJobOptions.camera");
  options.camera = "camera.csv";
  options.intrinsics = "camera.yaml";
  EXPECT_EQ(field_of(options), "ImportJobOptions.intrinsics");
  options.intrinsics.clear();
  options.read.units = io::LengthUnit::kMillimetre;
  EXPECT_EQ(field_of(options), "ImportOptions.units");
  options.read.units.reset();
  EXPECT_EQ(field_of(options), "no/such.json");  // valid: the reader fails on the file

  // matrix16 with one file has robot poses only: no camera table, and then it is valid.
  options = {};
  options.format = io::ImportFormat::kMatrix16;
  options.inputs = {"no/such.txt"};
  options.robot = "robot.csv";
  options.camera = "camera.csv";
  const InputError error = testing::Thrown<InputError>([&] { ImportSamples(options); });
  EXPECT_EQ(error.source(), "ImportJobOptions.camera");
  EXPECT_THAT(error.problem(), HasSubstr("only a robot file"));
  options.camera.clear();
  EXPECT_TRUE(options.IsValid(nullptr));
}

class ImportJobFiles : public testing::ScratchFolderTest {
 protected:
  ImportJobFiles() : ScratchFolderTest("import_job_test") {}
};

// A cali.txt whose lines hold two camera models has no single camera.yaml: refused naming the
// file; without the intrinsics file the same import succeeds.
TEST_F(ImportJobFiles, RefusesIntrinsicsThatDifferBetweenLines) {
  std::stringstream robot, cali;
  robot << std::ifstream(kTabb + "/robot_cali.txt").rdbuf();
  cali << std::ifstream(kTabb + "/cali.txt").rdbuf();
  std::string text = cali.str();
  const size_t fx = text.rfind("1081.59");
  ASSERT_NE(fx, std::string::npos);
  text.replace(fx, 7, "1090.00");
  ImportJobOptions options = TabbOptions();
  options.inputs = {Write("robot_cali.txt", robot.str()), Write("cali.txt", text)};
  const InputError error = testing::Thrown<InputError>([&] { ImportSamples(options); });
  EXPECT_EQ(error.source(), options.inputs.back());
  EXPECT_THAT(error.problem(), HasSubstr("do not share one camera model"));
  options.intrinsics.clear();
  EXPECT_FALSE(ImportSamples(options).texts.intrinsics.has_value());
}

}  // namespace
}  // namespace hecal::jobs
