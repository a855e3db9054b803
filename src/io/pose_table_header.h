// Private to src/io: the header line of a pose table (pose_table.h) — its column vocabulary,
// unit suffixes and the "# euler: SEQ" directive — and the unit conversions and message helpers
// that the reader, the writer and PairStations share.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/euler.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/pose_table.h"

namespace hecal::io::pose_table_internal {

// Rotation groups a header can hold. Presets that share a group with a plain format (ur = rotvec)
// are the same group.
enum class Group { kQuaternion, kAbb, kRotationVector, kMatrix, kEuler, kRpy, kKuka, kFanuc };
constexpr int kGroupCount = 8;

struct GroupInfo {
  std::string_view spelling;  // the --to spelling of the format
  int size;
  bool has_angles;  // rotation vector and Euler angles carry an angle unit
};

const GroupInfo& Info(Group group);

// Where each quantity sits in a row, and in which unit, as the header says.
struct Layout {
  size_t columns = 0;
  std::vector<std::string> names;  // as written, for messages
  int id = -1;
  int stamp = -1;
  std::array<int, 3> position = {-1, -1, -1};
  Group group = Group::kQuaternion;
  std::array<int, 9> rotation = {};
  LengthUnit unit = LengthUnit::kMetre;
  bool unit_named = false;  // a suffix (x_mm, x_m) fixed `unit`, not the options
  bool degrees = false;
  std::optional<EulerSequence> sequence;
  RotationFormat format;
};

// Parses the header fields at `line`: which column holds what, in which unit (suffixes win over
// `options`), and the rotation format. `declared_sequence` is the file's "# euler: SEQ", if any.
// Throws InputError for every header problem (unknown, duplicate or unnamed column, two or no
// rotation groups, missing columns, mixed or misplaced units, a1,a2,a3 without a sequence, a
// preset with a conflicting sequence).
Layout ParseHeader(const std::vector<Field>& fields, const std::string& source, int line,
                   const PoseReadOptions& options,
                   const std::optional<EulerSequence>& declared_sequence);

// The sequence declared by a comment line "# euler: SEQ" (case-insensitive key), or nullopt for
// any other comment.
std::optional<EulerSequence> EulerDirective(std::string_view comment_line);

// A printable, bounded ('...' after 40 characters, control bytes as \xNN) quoted copy of user
// text for one-line messages.
std::string Quoted(std::string_view text);
// "%.1e", for "how far off" in messages.
std::string Scientific(double value);

// File length unit → metres. Dividing by 1000 (rather than multiplying by 0.001) makes mm → m → mm
// reproduce the file's digits in more cases.
inline double ToMetres(double value, LengthUnit unit) {
  return unit == LengthUnit::kMillimetre ? value / 1000.0 : value;
}
inline double FromMetres(double value, LengthUnit unit) {
  return unit == LengthUnit::kMillimetre ? value * 1000.0 : value;
}
inline double ToRadians(double value, bool degrees) {
  return degrees ? value / kDegreesPerRadian : value;
}
inline double FromRadians(double value, bool degrees) {
  return degrees ? value * kDegreesPerRadian : value;
}

}  // namespace hecal::io::pose_table_internal
