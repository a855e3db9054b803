// Test support (not installed): a camera file in hecal's YAML form (docs/targets.md: fx, fy, cx,
// cy, width, height and the plumb_bob coefficients k1, k2, p1, p2, k3), written here without the
// library's writer so that the tests read hecal's reader against an independent file.
#pragma once

#include <iomanip>
#include <sstream>
#include <string>

#include "hecal/pose/camera_model.h"

namespace hecal::testing {

inline std::string CameraYaml(const pose::CameraModel& c) {
  std::ostringstream yaml;
  yaml << std::setprecision(17) << "fx: " << c.fx << "\nfy: " << c.fy << "\ncx: " << c.cx
       << "\ncy: " << c.cy << "\nwidth: " << c.width << "\nheight: " << c.height
       << "\ndistortion:\n  model: plumb_bob\n  coefficients: [" << c.distortion[0] << ", "
       << c.distortion[1] << ", " << c.distortion[2] << ", " << c.distortion[3] << ", "
       << c.distortion[4] << "]\n";
  return yaml.str();
}

}  // namespace hecal::testing
