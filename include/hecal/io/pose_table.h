// Pose tables: the CSV files hecal reads and writes (DESIGN.md §3, the contract).
//
// CSV, '#' starts a comment line, first non-comment line is the header. Columns by name:
// position x,y,z; exactly one rotation group (see rotation_format.h); optional id, stamp.
// Units: --units m|mm (default m) and --degrees, or header suffixes (x_mm, roll_deg) which win.
// Also accepted without a header: 16 numbers per line (row-major 4×4) or 12 numbers (3×4),
// separated by commas, tabs or spaces; units then come from the flags.
//
// In memory every pose is in metres and radians (the core's units); `unit` remembers the file's
// length unit so results can be written back in it.
// Readers throw hecal::InputError naming file, line, what is wrong and how to fix it.
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
  Pose pose = Pose::Identity();     // metres
  std::optional<std::string> id;    // the `id` column, when present
  std::optional<double> stamp;      // the `stamp` column (seconds), when present
  int line = 0;                     // 1-based line in the source file (for messages)
};

struct PoseTable {
  std::vector<PoseRow> rows;
  std::string source;                         // file name, for messages
  LengthUnit unit = LengthUnit::kMetre;       // the file's length unit
  std::optional<RotationFormat> rotation;     // the rotation group found (nullopt: matrix lines)
};

struct PoseReadOptions {
  LengthUnit units = LengthUnit::kMetre;      // --units; header suffixes win
  bool degrees = false;                       // --degrees; header suffixes win
  std::optional<EulerSequence> euler;         // --euler SEQ, for a1,a2,a3 columns
  bool invert = false;                        // replace every pose by its inverse after reading
};

struct PoseWriteOptions {
  RotationFormat rotation;                    // --to
  LengthUnit units = LengthUnit::kMetre;      // --units
  bool degrees = false;                       // --degrees (presets kuka/fanuc default to degrees)
  bool write_id = true;                       // write the id column when rows have ids
  bool write_stamp = true;                    // write the stamp column when rows have stamps
  std::vector<std::string> comments;          // '#' lines written before the header
};

PoseTable ReadPoseTable(const std::string& path, const PoseReadOptions& options);
// Same, from text already in memory; `source` names it in messages.
PoseTable ParsePoseTable(std::string_view text, const std::string& source,
                         const PoseReadOptions& options);

std::string FormatPoseTable(const PoseTable& table, const PoseWriteOptions& options);
// Writes atomically (temporary file, then rename): never a partial file.
void WritePoseTable(const std::string& path, const PoseTable& table,
                    const PoseWriteOptions& options);

// Robot and camera rows paired into stations: by `id` when both tables have ids, else by order.
struct Stations {
  std::vector<Pose> robot;   // T_base_gripper_i
  std::vector<Pose> camera;  // T_camera_target_i
  std::vector<std::string> ids;  // the id, or the 0-based row index as text
};
// Throws InputError when lengths differ, ids do not match, or an id repeats.
Stations PairStations(const PoseTable& robot, const PoseTable& camera);

}  // namespace hecal::io
