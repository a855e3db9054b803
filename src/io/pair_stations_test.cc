#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "hecal/core/error.h"
#include "hecal/io/pose_table.h"
#include "testing/elementary_rotations.h"

namespace hecal::io {
namespace {

using ::testing::HasSubstr;

// ---- pairing
// -------------------------------------------------------------------------------------

PoseTable TableWithIds(const std::string& source, const std::vector<std::string>& ids) {
  PoseTable table;
  table.source = source;
  for (size_t i = 0; i < ids.size(); ++i) {
    PoseRow row;
    row.pose = MakePose(testing::Rz(0.1 * static_cast<double>(i)), Eigen::Vector3d::Zero());
    if (!ids[i].empty()) row.id = ids[i];
    row.line = static_cast<int>(i) + 2;
    table.rows.push_back(row);
  }
  return table;
}

TEST(PairStationsTest, ById) {
  const PoseTable robot = TableWithIds("robot.csv", {"a", "b", "c"});
  const PoseTable camera = TableWithIds("camera.csv", {"c", "a", "b"});
  const Stations stations = PairStations(robot, camera);
  ASSERT_EQ(stations.ids, (std::vector<std::string>{"a", "b", "c"}));
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(stations.robot[i].isApprox(robot.rows[i].pose));
  }
  EXPECT_TRUE(stations.camera[0].isApprox(camera.rows[1].pose));  // a
  EXPECT_TRUE(stations.camera[2].isApprox(camera.rows[0].pose));  // c
}

TEST(PairStationsTest, ByOrderWhenEitherHasNoIds) {
  const PoseTable robot = TableWithIds("robot.csv", {"a", "b"});
  const PoseTable camera = TableWithIds("camera.csv", {"", ""});
  const Stations stations = PairStations(robot, camera);
  EXPECT_EQ(stations.ids, (std::vector<std::string>{"0", "1"}));
  EXPECT_TRUE(stations.camera[1].isApprox(camera.rows[1].pose));
}

TEST(PairStationsTest, DifferentLengths) {
  try {
    PairStations(TableWithIds("robot.csv", {"", "", ""}), TableWithIds("camera.csv", {"", ""}));
    FAIL();
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("robot.csv"));
    EXPECT_THAT(error.what(), HasSubstr("3 poses"));
    EXPECT_THAT(error.what(), HasSubstr("camera.csv has 2"));
  }
}

TEST(PairStationsTest, UnmatchedIdNamesTheIdAndLine) {
  try {
    PairStations(TableWithIds("robot.csv", {"a", "b", "x"}),
                 TableWithIds("camera.csv", {"a", "b", "c"}));
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "robot.csv");
    EXPECT_EQ(error.line(), 4);
    EXPECT_THAT(error.what(), HasSubstr("id 'x' has no row in camera.csv"));
  }
  try {
    PairStations(TableWithIds("robot.csv", {"a", "b"}),
                 TableWithIds("camera.csv", {"a", "b", "c"}));
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "camera.csv");
    EXPECT_EQ(error.line(), 4);
    EXPECT_THAT(error.what(), HasSubstr("id 'c' has no row in robot.csv"));
  }
}

TEST(PairStationsTest, RepeatedIdInAnInMemoryTable) {
  EXPECT_THROW(
      PairStations(TableWithIds("robot.csv", {"a", "a"}), TableWithIds("camera.csv", {"a", "b"})),
      InputError);
  EXPECT_THROW(
      PairStations(TableWithIds("robot.csv", {"a", "b"}), TableWithIds("camera.csv", {"b", "b"})),
      InputError);
}

}  // namespace
}  // namespace hecal::io
