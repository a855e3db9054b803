// target.yaml → pose::TargetSpec (DESIGN.md §4.1; every key and type in docs/targets.md).
//
//   type: charuco          # chessboard | charuco | aruco_grid | apriltag_grid | circles | acircles
//   cols: 5                # chessboard/circles/acircles: points along x; charuco: squares; grids:
//   markers rows: 7 square: 28.157         # chessboard/charuco square side; circles/acircles pitch
//   marker: 17.6           # charuco / grids: marker side
//   spacing: 6.6           # grids: gap between markers
//   dictionary: DICT_5X5_250   # charuco / aruco_grid: an OpenCV 4.6 predefined dictionary name
//   family: tag36h11       # apriltag_grid: a libapriltag family
//   first_id: 0            # grids, optional: id of the top-left marker (default 0)
//   units: mm              # optional: m (default) or mm; lengths are returned in metres
//
// The keys a type needs are pose::TargetFieldUse's; the values are checked by pose::CheckTarget
// (counts ≥ 2, charuco ≥ 3 squares and marker < square, positive lengths, known dictionary /
// family names with enough ids, odd rows for acircles). Dictionary and family names are the
// tables in pose/target.h (strings: io does not link OpenCV or libapriltag).
//
// Errors: hecal::InputError(file, line, problem, fix) with the line of the offending key
// (yaml-cpp's mark) for: invalid YAML, a document that is not a map, unknown keys (with a "did you
// mean" suggestion), keys given twice, keys the type does not use, missing keys the type needs,
// values of the wrong kind (a list for a number, 2.5 for a count), unknown type / units /
// dictionary / family names, and every CheckTarget problem.
#pragma once

#include <string>
#include <string_view>

#include "hecal/pose/target.h"

namespace hecal::io {

pose::TargetSpec ReadTargetFile(const std::string& path);

// The same from text; `source` names it in errors.
pose::TargetSpec ParseTargetYaml(std::string_view text, const std::string& source);

}  // namespace hecal::io
