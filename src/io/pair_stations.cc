// PairStations (pose_table.h): robot and camera rows into stations, by id or by order.
#include <algorithm>
#include <string_view>
#include <unordered_map>

#include "hecal/core/error.h"
#include "hecal/io/pose_table.h"
#include "pose_table_header.h"

namespace hecal::io {

using pose_table_internal::Quoted;

Stations PairStations(const PoseTable& robot, const PoseTable& camera) {
  const auto all_have_ids = [](const PoseTable& table) {
    return !table.rows.empty() &&
           std::all_of(table.rows.begin(), table.rows.end(),
                       [](const PoseRow& row) { return row.id.has_value(); });
  };
  Stations stations;
  if (all_have_ids(robot) && all_have_ids(camera)) {
    std::unordered_map<std::string_view, const PoseRow*> camera_rows;
    for (const PoseRow& row : camera.rows) {
      if (const auto [it, inserted] = camera_rows.emplace(*row.id, &row); !inserted) {
        throw InputError(camera.source, row.line,
                         "id " + Quoted(*row.id) + " repeats (first at line " +
                             std::to_string(it->second->line) + ")",
                         "give every row its own id");
      }
    }
    std::unordered_map<std::string_view, int> robot_lines;
    for (const PoseRow& row : robot.rows) {
      if (const auto [it, inserted] = robot_lines.emplace(*row.id, row.line); !inserted) {
        throw InputError(
            robot.source, row.line,
            "id " + Quoted(*row.id) + " repeats (first at line " + std::to_string(it->second) + ")",
            "give every row its own id");
      }
      const auto match = camera_rows.find(*row.id);
      if (match == camera_rows.end()) {
        throw InputError(robot.source, row.line,
                         "id " + Quoted(*row.id) + " has no row in " + camera.source,
                         "make both files list the same ids (or drop the id columns to pair by "
                         "order)");
      }
      stations.robot.push_back(row.pose);
      stations.camera.push_back(match->second->pose);
      stations.ids.push_back(*row.id);
    }
    for (const PoseRow& row : camera.rows) {
      if (!robot_lines.contains(*row.id)) {
        throw InputError(camera.source, row.line,
                         "id " + Quoted(*row.id) + " has no row in " + robot.source,
                         "make both files list the same ids (or drop the id columns to pair by "
                         "order)");
      }
    }
    return stations;
  }
  if (robot.rows.size() != camera.rows.size()) {
    throw InputError(robot.source, 0,
                     "has " + std::to_string(robot.rows.size()) + " poses but " + camera.source +
                         " has " + std::to_string(camera.rows.size()),
                     "give both files one row per station, in the same order (or add an id "
                     "column to both)");
  }
  for (size_t i = 0; i < robot.rows.size(); ++i) {
    stations.robot.push_back(robot.rows[i].pose);
    stations.camera.push_back(camera.rows[i].pose);
    stations.ids.push_back(std::to_string(i));
  }
  return stations;
}

}  // namespace hecal::io
