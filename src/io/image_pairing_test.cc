// PairRobotWithStations (image_pairing.h): rows pair with stations by id when the ids name
// stations, else by order; each rule's errors and notes.
#include "hecal/io/image_pairing.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "testing/thrown.h"

namespace hecal::io {
namespace {

// Row k holds a pose translated by k along x, so a pose tells which row it came from.
PoseTable Robot(const std::vector<std::string>& ids) {
  PoseTable table;
  table.source = "robot.csv";
  for (std::size_t k = 0; k < ids.size(); ++k) {
    PoseRow row;
    row.pose.translation() = Eigen::Vector3d(static_cast<double>(k), 0, 0);
    if (!ids[k].empty()) row.id = ids[k];
    row.line = static_cast<int>(k) + 2;
    table.rows.push_back(row);
  }
  return table;
}

std::vector<StationImage> StationsNamed(const std::vector<std::string>& ids) {
  std::vector<StationImage> stations;
  for (const std::string& id : ids) stations.push_back({id, "images/" + id + ".png", id + ".png"});
  return stations;
}

std::vector<double> Rows(const std::vector<Pose>& poses) {
  std::vector<double> rows;
  for (const Pose& pose : poses) rows.push_back(pose.translation().x());
  return rows;
}

TEST(PairRobotWithStationsTest, ByIdInTheStationsOrderWithSpareRowsNoted) {
  std::vector<std::string> notes;
  const std::vector<Pose> poses = PairRobotWithStations(
      Robot({"im_2", "im_0", "im_9", "im_1"}), StationsNamed({"im_0", "im_1", "im_2"}), "images",
      [&](const std::string& note) { notes.push_back(note); });
  EXPECT_EQ(Rows(poses), (std::vector<double>{1, 3, 0}));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "robot.csv:4: id 'im_9' has no image in images; left out");
}

TEST(PairRobotWithStationsTest, ByOrderWithoutIdsOrWhenNoIdNamesAStation) {
  EXPECT_EQ(Rows(PairRobotWithStations(Robot({"", "", ""}), StationsNamed({"a", "b", "c"}),
                                       "images", {})),
            (std::vector<double>{0, 1, 2}));
  std::vector<std::string> notes;
  EXPECT_EQ(
      Rows(PairRobotWithStations(Robot({"1", "2", "3"}), StationsNamed({"a", "b", "c"}), "images",
                                 [&](const std::string& note) { notes.push_back(note); })),
      (std::vector<double>{0, 1, 2}));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("no id equals an image's file stem"), std::string::npos) << notes[0];
}

TEST(PairRobotWithStationsTest, ErrorsNameTheRobotFile) {
  InputError error = testing::Thrown<InputError>([] {
    PairRobotWithStations(Robot({"", ""}), StationsNamed({"a", "b", "c"}), "images", {});
  });
  EXPECT_EQ(error.source(), "robot.csv");
  EXPECT_EQ(error.problem(), "has 2 poses but images has 3 images");

  error = testing::Thrown<InputError>([] {
    PairRobotWithStations(Robot({"a", "b", "a"}), StationsNamed({"a", "b"}), "images", {});
  });
  EXPECT_EQ(error.line(), 4);
  EXPECT_EQ(error.problem(), "id 'a' repeats (first at line 2)");

  error = testing::Thrown<InputError>([] {
    PairRobotWithStations(Robot({"a", "b"}), StationsNamed({"a", "c"}), "images", {});
  });
  EXPECT_EQ(error.problem(), "no row with id 'c' for the image c.png");
}

}  // namespace
}  // namespace hecal::io
