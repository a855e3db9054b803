// Pose tables: the CSV files hecal reads and writes (the contract; the full rules,
// with examples, are in docs/pose-files.md).
//
// Reading
//   '#' lines are comments, blank lines are skipped; the first other line is the header, naming
//   columns in any order, case-insensitively: position x,y,z; exactly one rotation group (see
//   rotation_format.h: qw,qx,qy,qz | q1..q4 | rx,ry,rz | r11..r33 | a1,a2,a3 | roll,pitch,yaw |
//   a,b,c | w,p,r); optional id (unique, non-empty text) and stamp (seconds). Comma-separated
//   (fields trimmed, "double quotes" as in RFC 4180), or whitespace-separated when the header has
//   no comma. CRLF and a UTF-8 BOM are accepted.
//   Units: suffixes x_mm / x_m and _deg / _rad on angle columns win over the options; otherwise
//   lengths are in options.units and angles in radians unless options.degrees (kuka a,b,c and
//   fanuc w,p,r default to degrees). The three position columns share one suffix (or none), as
//   do the angle columns.
//   a1,a2,a3 take their sequence from a "# euler: SEQ" comment before the header (which wins) or
//   from options.euler; preset columns have their own sequence and reject a different one.
//   Without a header: 12 (3×4) or 16 (4×4, last row 0 0 0 1 within 1e-9) numbers per line,
//   separated by commas and/or spaces/tabs, lengths in options.units.
//   Rotation matrices (r11..r33, matrix lines) and quaternions (qw..qz, q1..q4) follow the rule
//   of rotation_input.h: within 1e-6 of a rotation they are projected (normalised) silently,
//   within the tolerance (1e-3, widened for coarsely printed entries, at most 1e-2) projected
//   with one note per file in PoseTable::warnings, beyond it refused with the reason (a
//   reflection, a scaled rotation, too few digits, not orthonormal; a zero or non-unit
//   quaternion). Rotation vectors are taken modulo 2π.
//   Every pose in memory is in metres and radians; `unit` remembers the file's length unit and
//   `unit_named` whether the file itself said it (a header suffix).
//   Errors throw hecal::InputError(file, line, what, fix), one line each: NaN/Inf, not a number,
//   wrong value count, unknown (with a suggestion), duplicate or unnamed column, two rotation
//   groups, missing position/rotation columns, mixed or misplaced units, missing Euler sequence,
//   a matrix or quaternion that is not a rotation (with why), bad 4×4 last row, empty file or
//   header only, duplicate or empty id, unclosed quote, unreadable file.
//
// Writing
//   Optional '#' comments, then the header: id and stamp (when the rows have them and the options
//   keep them), x,y,z, the rotation group. Units other than metres/radians are in the header
//   (x_mm, rx_deg, a_deg), and euler:SEQ output starts with "# euler: SEQ", so a written file
//   reads back to the same poses with default options. Numbers are the shortest text that reads
//   back to the same double (values converted to mm or degrees: the shortest that converts back
//   exactly, so 123.456 mm stays "123.456"). Quaternions have w ≥ 0, rotation vectors |ω| ≤ π,
//   Euler angles are EulerFromMatrix's. Ids are quoted when needed.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/io/rotation_format.h"
#include "hecal/io/units.h"

namespace hecal::io {

struct PoseRow {
  Pose pose = Pose::Identity();   // metres
  std::optional<std::string> id;  // the `id` column, when present
  std::optional<double> stamp;    // the `stamp` column (seconds), when present
  int line = 0;                   // 1-based line in the source file (for messages)
};

struct PoseTable {
  std::vector<PoseRow> rows;
  std::string source;                    // file name, for messages
  LengthUnit unit = LengthUnit::kMetre;  // the file's length unit
  // Set by ReadPoseTable/ParsePoseTable: true when the file fixed `unit` itself (a header suffix:
  // x_mm, x_m); false when it came from PoseReadOptions::units (the --units flag or its default),
  // as for every matrix-line file. (The importers, import.h, leave it false.)
  bool unit_named = false;
  std::optional<RotationFormat> rotation;  // the rotation group found (nullopt: matrix lines)
  bool degrees = false;                    // the file's angles were in degrees (rotvec/Euler)
  // One line per note, starting with the file name: rotations that were not exactly orthonormal
  // or unit (rotation_input.h), e.g. "robot.csv: 3 of 88 rotation matrices were not ...".
  std::vector<std::string> warnings;
};

struct PoseReadOptions {
  LengthUnit units = LengthUnit::kMetre;  // --units; header suffixes win
  bool degrees = false;                   // --degrees; header suffixes win
  std::optional<EulerSequence> euler;     // --euler SEQ, for a1,a2,a3 columns
  bool invert = false;                    // replace every pose by its inverse after reading

  // core/options_check.h: false naming PoseReadOptions.units (not a LengthUnit). The other fields
  // hold any value their type allows (an EulerSequence is valid when it exists).
  bool IsValid(std::string* why) const;
};

struct PoseWriteOptions {
  RotationFormat rotation;                // --to
  LengthUnit units = LengthUnit::kMetre;  // --units
  bool degrees = false;                   // --degrees (presets kuka/fanuc default to degrees)
  bool write_id = true;                   // write the id column when rows have ids
  bool write_stamp = true;                // write the stamp column when rows have stamps
  std::vector<std::string> comments;      // '#' lines written before the header

  // core/options_check.h: false naming PoseWriteOptions.rotation (not a rotation kind, or an
  // Euler format without a sequence or another with one) or .units (not a LengthUnit).
  bool IsValid(std::string* why) const;
};

// Reads `path` (InputError when unreadable) and parses it; `source` of the table and of every
// error is `path`. Both forms throw hecal::InputError when !options.IsValid.
PoseTable ReadPoseTable(const std::string& path, const PoseReadOptions& options);
// Same, from text already in memory; `source` names it in messages.
PoseTable ParsePoseTable(std::string_view text, const std::string& source,
                         const PoseReadOptions& options);

// The file text. Throws InputError when a value does not fit in a double in the output unit
// (|x| > ~1.8e305 m written in mm), when only some rows have ids or stamps, or when an id holds
// a line break, or when !options.IsValid.
std::string FormatPoseTable(const PoseTable& table, const PoseWriteOptions& options);
// Writes atomically (temporary file, then rename): never a partial file.
void WritePoseTable(const std::string& path, const PoseTable& table,
                    const PoseWriteOptions& options);

// Robot and camera rows paired into stations: by `id` when every row of both tables has one (in
// the robot table's order), else by order.
struct Stations {
  std::vector<Pose> robot;       // T_base_gripper_i
  std::vector<Pose> camera;      // T_camera_target_i
  std::vector<std::string> ids;  // the id, or the 0-based row index as text
};
// Throws InputError when lengths differ (by order), when an id of one table is missing from the
// other (naming the first such id and its line), or when an id repeats.
Stations PairStations(const PoseTable& robot, const PoseTable& camera);

}  // namespace hecal::io
