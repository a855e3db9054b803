// The pivot calibration's result file (docs/pivot.md#the-result-file, the contract): JSON, or
// YAML when the path ends in .yaml / .yml (report/yaml_tree.h), written atomically.
//
// Units as docs/result-file.md: lengths in `units.length` (the robot file's unit), angles in
// radians except fields whose name ends in _deg; the covariance of (t_tip, p) in unit².
//   {"hecal_version", "kind": "pivot", "units": {"length", "angle"},
//    "tip": {"frame": "flange", "translation": [3], "sigma": [3]},
//    "pivot": {"frame": "base", "translation": [3], "sigma": [3]},
//    "covariance": {"matrix": 6×6, "order": "tip x y z (flange), pivot x y z (base)"},
//    "algebraic": {"tip": [3], "pivot": [3]},
//    "noise": {"robot_sigma": {"rotation_deg", "translation"}, "estimated", "chi_square", "dof"},
//    "residuals": {"rms", "outlier_chi_square", "per_station": [{"id", "residual": [3],
//                  "distance", "standardized", "outlier", "used"}]},
//    "stations": {"used": [ids], "rejected": [ids], "outlier_rejection"},
//    "min_tilt_deg", "iterations", "warnings": [...]}
#pragma once

#include <string>
#include <vector>

#include "hecal/estimation/pivot.h"
#include "hecal/io/units.h"
#include "hecal/report/result_file.h"

namespace hecal::report {

// A pivot calibration with what the file says about its input.
struct PivotDocument {
  estimation::PivotResult result;                // metres, radians
  io::LengthUnit unit = io::LengthUnit::kMetre;  // the file's length unit
  std::vector<std::string> station_ids;          // one per station
  bool outlier_rejection = true;                 // PivotOptions::reject_outliers
};

std::string FormatPivotResult(const PivotDocument& document, ResultFormat format);
// Atomic write (never a partial file), the format by the path's extension.
void WritePivotResult(const std::string& path, const PivotDocument& document);

}  // namespace hecal::report
