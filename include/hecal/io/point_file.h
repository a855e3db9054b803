// Point files (`hecal pose` object and image points, `hecal contour` contours; docs/cli.md): CSV,
// or whitespace-separated when the header has no comma; '#' comment lines; the first other line
// is the header, naming the value columns (case-insensitive) and optionally `id`. Object points
// are in the target frame, in metres after reading (a `_m` / `_mm` suffix on the value columns,
// else the given unit); image points in pixels (docs/pose-from-points.md). Every error is a
// hecal::InputError naming file:line, what is wrong and how to fix it: an unreadable file, a
// missing, unknown or repeated column, mixed unit suffixes, a row with the wrong number of
// values, a value that is not a finite number, an empty or repeated id, no point.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/io/units.h"

namespace hecal::io {

struct PointRow {
  std::optional<std::string> id;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();  // x, y, z (metres) or u, v, 0 (pixels)
  int line = 0;
};

struct PointFile {
  std::string source;
  std::vector<PointRow> rows;
  bool has_ids = false;
  LengthUnit unit = LengthUnit::kMetre;  // object files: the file's length unit
};

// Reads a point file with an optional id column and the value columns `names` (x,y,z; u,v; x,y).
// With `lengths`, the value columns may carry one shared unit suffix (_m, _mm) that wins over
// `unit`, and values are converted to metres. Ids must be unique; at least one point.
// `what` names the points in messages ("object points").
PointFile ReadPointFile(const std::string& path, std::span<const std::string_view> names,
                        bool lengths, LengthUnit unit, std::string_view what);

}  // namespace hecal::io
