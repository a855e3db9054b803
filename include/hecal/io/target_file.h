// target.yaml → pose::TargetSpec (every key and type in docs/targets.md).
//
//   type: charuco          # chessboard | charuco | aruco_grid | apriltag_grid | circles | acircles
//                          # | aruco | apriltag (one tag)
//   cols: 5                # chessboard/circles/acircles: points along x; charuco: squares;
//   rows: 7                #   grids: markers (not for single tags)
//   square: 28.157         # chessboard/charuco square side; circles/acircles pitch
//   marker: 17.6           # charuco / grids: marker side
//   spacing: 6.6           # grids: gap between markers
//   dictionary: DICT_5X5_250   # charuco / aruco_grid / aruco: an OpenCV 4.6 dictionary name
//   family: tag36h11       # apriltag_grid / apriltag: a libapriltag family
//   first_id: 0            # grids, optional: id of the top-left marker (default 0)
//   id: 12                 # aruco / apriltag: the tag's id
//   size: 80               # aruco / apriltag: the tag's side
//   units: mm              # optional: m (default) or mm; lengths are returned in metres
//
// The keys a type needs are pose::TargetFieldUse's; the values are checked by pose::CheckTarget
// (counts ≥ 2, charuco ≥ 3 squares and marker < square, positive lengths, known dictionary /
// family names with enough ids, odd rows for acircles). Dictionary and family names are the
// tables in pose/target.h (strings: io does not link OpenCV or libapriltag).
//
// Units. Lengths a printed target plausibly has are 1 mm ≤ length < 1 m. Outside that range the
// unit is the likely mistake, so the reader refuses (each a length as written, its key's line):
//   - without `units`, a length ≥ 1 (metres): millimetres written without `units: mm`
//     ("square 15 m is not a plausible target square"; fix: add `units: mm`);
//   - with `units: mm`, a length < 1 mm: metres marked as millimetres ("... it looks like
//     metres"; fix: remove `units: mm`).
// An explicit `units: m` is taken at its word (a 1.2 m tag is possible; so is a 0.5 mm square
// for a microscope), and lengths in millimetres from 1 m up are accepted with `units: mm`.
//
// Errors: hecal::InputError(file, line, problem, fix) with the line of the offending key
// (yaml-cpp's mark) for: invalid YAML, a document that is not a map, unknown keys (with a "did you
// mean" suggestion), keys given twice, keys the type does not use (a single tag's `marker` or
// `first_id`, a grid's `size` or `id`: "rename the key"), missing keys the type needs, values of
// the wrong kind (a list for a number, 2.5 for a count), unknown type / units / dictionary /
// family names, implausible lengths (above), and every CheckTarget problem.
#pragma once

#include <string>
#include <string_view>

#include "hecal/pose/target.h"

namespace hecal::io {

pose::TargetSpec ReadTargetFile(const std::string& path);

// The same from text; `source` names it in errors.
pose::TargetSpec ParseTargetYaml(std::string_view text, const std::string& source);

}  // namespace hecal::io
