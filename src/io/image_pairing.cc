// Robot rows paired with image stations: see image_pairing.h.
#include "hecal/io/image_pairing.h"

#include <algorithm>
#include <map>

#include "hecal/core/error.h"

namespace hecal::io {

std::vector<Pose> PairRobotWithStations(const PoseTable& robot,
                                        const std::vector<StationImage>& stations,
                                        const std::string& images_dir,
                                        const std::function<void(const std::string&)>& note) {
  const auto say = [&note](const std::string& text) {
    if (note) note(text);
  };
  const bool have_ids =
      !robot.rows.empty() && std::all_of(robot.rows.begin(), robot.rows.end(),
                                         [](const PoseRow& row) { return row.id.has_value(); });
  const bool by_id =
      have_ids && std::any_of(robot.rows.begin(), robot.rows.end(), [&](const PoseRow& row) {
        return std::any_of(stations.begin(), stations.end(),
                           [&row](const StationImage& station) { return station.id == *row.id; });
      });
  if (have_ids && !by_id) {
    say(robot.source +
        ": no id equals an image's file stem; pairing the rows with the images in sorted "
        "file-name order");
  }
  std::vector<Pose> poses;
  if (!by_id) {
    if (robot.rows.size() != stations.size()) {
      throw InputError(robot.source, 0,
                       "has " + std::to_string(robot.rows.size()) + " poses but " + images_dir +
                           " has " + std::to_string(stations.size()) + " images",
                       "give one robot pose per image file, in sorted file-name order (images "
                       "where the target is not found count too), or add an id column equal to "
                       "each image's file stem");
    }
    for (const PoseRow& row : robot.rows) poses.push_back(row.pose);
    return poses;
  }
  std::map<std::string, const PoseRow*> rows;
  for (const PoseRow& row : robot.rows) {
    if (const auto [it, inserted] = rows.emplace(*row.id, &row); !inserted) {
      throw InputError(
          robot.source, row.line,
          "id '" + *row.id + "' repeats (first at line " + std::to_string(it->second->line) + ")",
          "give every row its own id");
    }
  }
  for (const StationImage& station : stations) {
    const auto match = rows.find(station.id);
    if (match == rows.end()) {
      throw InputError(robot.source, 0,
                       "no row with id '" + station.id + "' for the image " + station.name,
                       "add the robot pose of that image with id '" + station.id +
                           "', remove the image, or drop the id column to pair by sorted name");
    }
    poses.push_back(match->second->pose);
    rows.erase(match);
  }
  for (const auto& [id, row] : rows) {
    say(robot.source + ":" + std::to_string(row->line) + ": id '" + id + "' has no image in " +
        images_dir + "; left out");
  }
  return poses;
}

}  // namespace hecal::io
