// Test support (not installed): poses as the text of a pose table (docs/pose-files.md), for tests
// that write the robot and camera files of a known scene. One row per pose: id s0, s1, …, the
// translation x, y, z multiplied by `scale` under column names suffixed with `unit` ("_mm" with
// scale 1e3; "" for the unit of --units), then the Hamilton quaternion qw, qx, qy, qz of the
// rotation; 17 significant digits, so a pose read back equals the one written to rounding.
#pragma once

#include <Eigen/Geometry>
#include <sstream>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"

namespace hecal::testing {

inline std::string PoseCsv(const std::vector<Pose>& poses, double scale = 1.0,
                           const std::string& unit = "") {
  std::ostringstream csv;
  csv.precision(17);
  csv << "id,x" << unit << ",y" << unit << ",z" << unit << ",qw,qx,qy,qz\n";
  for (size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Quaterniond q(poses[i].linear());
    const Eigen::Vector3d t = poses[i].translation() * scale;
    csv << "s" << i << "," << t.x() << "," << t.y() << "," << t.z() << "," << q.w() << "," << q.x()
        << "," << q.y() << "," << q.z() << "\n";
  }
  return csv.str();
}

}  // namespace hecal::testing
