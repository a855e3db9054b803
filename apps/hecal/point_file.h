// Point files of the CLI (`hecal pose` object and image points, `hecal contour` contours): CSV,
// or whitespace-separated when the header has no comma; '#' comment lines; the first other line
// is the header, naming the value columns (case-insensitive) and optionally `id`. Every error is
// a hecal::InputError naming file:line, what is wrong and how to fix it.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/io/units.h"

namespace hecal::cli {

struct PointRow {
  std::optional<std::string> id;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();  // x, y, z (metres) or u, v, 0 (pixels)
  int line = 0;
};

struct PointFile {
  std::string source;
  std::vector<PointRow> rows;
  bool has_ids = false;
  io::LengthUnit unit = io::LengthUnit::kMetre;  // object files: the file's length unit
};

// Reads a point file with an optional id column and the value columns `names` (x,y,z; u,v; x,y).
// With `lengths`, the value columns may carry one shared unit suffix (_m, _mm) that wins over
// `unit`, and values are converted to metres. Ids must be unique; at least one point.
// `what` names the points in messages ("object points").
PointFile ReadPointFile(const std::string& path, std::span<const std::string_view> names,
                        bool lengths, io::LengthUnit unit, std::string_view what);

}  // namespace hecal::cli
