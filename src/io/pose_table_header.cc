#include "pose_table_header.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <unordered_map>

#include "closest_name.h"
#include "hecal/core/error.h"
#include "hecal/io/delimited_text.h"

namespace hecal::io::pose_table_internal {
namespace {

constexpr std::array<GroupInfo, kGroupCount> kGroups = {{
    {"quaternion", 4, false},
    {"abb", 4, false},
    {"rotvec", 3, true},
    {"matrix", 9, false},
    {"euler", 3, true},
    {"rpy", 3, true},
    {"kuka", 3, true},
    {"fanuc", 3, true},
}};

enum class Role { kPosition, kId, kStamp, kRotation };

struct KnownColumn {
  std::string_view name;
  Role role;
  Group group;  // for kRotation
  int index;    // position axis or index within the rotation group
};

constexpr KnownColumn kKnownColumns[] = {
    {"x", Role::kPosition, Group::kQuaternion, 0},
    {"y", Role::kPosition, Group::kQuaternion, 1},
    {"z", Role::kPosition, Group::kQuaternion, 2},
    {"id", Role::kId, Group::kQuaternion, 0},
    {"stamp", Role::kStamp, Group::kQuaternion, 0},
    {"qw", Role::kRotation, Group::kQuaternion, 0},
    {"qx", Role::kRotation, Group::kQuaternion, 1},
    {"qy", Role::kRotation, Group::kQuaternion, 2},
    {"qz", Role::kRotation, Group::kQuaternion, 3},
    {"q1", Role::kRotation, Group::kAbb, 0},
    {"q2", Role::kRotation, Group::kAbb, 1},
    {"q3", Role::kRotation, Group::kAbb, 2},
    {"q4", Role::kRotation, Group::kAbb, 3},
    {"rx", Role::kRotation, Group::kRotationVector, 0},
    {"ry", Role::kRotation, Group::kRotationVector, 1},
    {"rz", Role::kRotation, Group::kRotationVector, 2},
    {"r11", Role::kRotation, Group::kMatrix, 0},
    {"r12", Role::kRotation, Group::kMatrix, 1},
    {"r13", Role::kRotation, Group::kMatrix, 2},
    {"r21", Role::kRotation, Group::kMatrix, 3},
    {"r22", Role::kRotation, Group::kMatrix, 4},
    {"r23", Role::kRotation, Group::kMatrix, 5},
    {"r31", Role::kRotation, Group::kMatrix, 6},
    {"r32", Role::kRotation, Group::kMatrix, 7},
    {"r33", Role::kRotation, Group::kMatrix, 8},
    {"a1", Role::kRotation, Group::kEuler, 0},
    {"a2", Role::kRotation, Group::kEuler, 1},
    {"a3", Role::kRotation, Group::kEuler, 2},
    {"roll", Role::kRotation, Group::kRpy, 0},
    {"pitch", Role::kRotation, Group::kRpy, 1},
    {"yaw", Role::kRotation, Group::kRpy, 2},
    {"a", Role::kRotation, Group::kKuka, 0},
    {"b", Role::kRotation, Group::kKuka, 1},
    {"c", Role::kRotation, Group::kKuka, 2},
    {"w", Role::kRotation, Group::kFanuc, 0},
    {"p", Role::kRotation, Group::kFanuc, 1},
    {"r", Role::kRotation, Group::kFanuc, 2},
};

constexpr std::string_view kValidColumnsText =
    "position x,y,z (suffix _m or _mm); one rotation group: qw,qx,qy,qz | rx,ry,rz | r11..r33 | "
    "a1,a2,a3 (with --euler SEQ) | roll,pitch,yaw | a,b,c | w,p,r | q1,q2,q3,q4 (angles may end in "
    "_deg or _rad); optional id, stamp";

const KnownColumn* FindColumn(std::string_view name) {
  for (const KnownColumn& column : kKnownColumns) {
    if (column.name == name) return &column;
  }
  return nullptr;
}

// The column names of a group, comma-separated, for messages.
std::string GroupColumnsText(Group group) {
  std::string text;
  for (const KnownColumn& column : kKnownColumns) {
    if (column.role == Role::kRotation && column.group == group) {
      if (!text.empty()) text += ",";
      text += column.name;
    }
  }
  return text;
}

// A likely intended column for an unknown name, or "".
std::string SuggestColumn(std::string_view name) {
  static constexpr std::pair<std::string_view, std::string_view> kAliases[] = {
      {"tx", "x"},       {"ty", "y"},      {"tz", "z"},
      {"time", "stamp"}, {"t", "stamp"},   {"timestamp", "stamp"},
      {"index", "id"},   {"name", "id"},   {"image", "id"},
      {"qw_", "qw"},     {"angle1", "a1"}, {"angle2", "a2"},
      {"angle3", "a3"},
  };
  for (const auto& [alias, column] : kAliases) {
    if (name == alias) return std::string(column);
  }
  if (name.size() > 64) return "";
  std::string best;
  size_t best_distance = 3;
  for (const KnownColumn& column : kKnownColumns) {
    const size_t distance = internal::EditDistance(name, column.name);
    // Single-letter names are only suggested for a one-character slip.
    const size_t limit = column.name.size() == 1 ? 1 : 2;
    if (distance <= limit && distance < best_distance) {
      best_distance = distance;
      best = column.name;
    }
  }
  return best;
}

enum class Suffix { kNone, kMetre, kMillimetre, kDegree, kRadian };

std::string_view SuffixText(Suffix suffix) {
  switch (suffix) {
    case Suffix::kNone:
      return "";
    case Suffix::kMetre:
      return "_m";
    case Suffix::kMillimetre:
      return "_mm";
    case Suffix::kDegree:
      return "_deg";
    case Suffix::kRadian:
      return "_rad";
  }
  return "";
}

// Splits "x_mm" into ("x", kMillimetre). Only a known base name loses its suffix.
std::pair<std::string_view, Suffix> SplitSuffix(std::string_view name) {
  for (Suffix suffix : {Suffix::kMillimetre, Suffix::kMetre, Suffix::kDegree, Suffix::kRadian}) {
    const std::string_view text = SuffixText(suffix);
    if (name.size() > text.size() && name.ends_with(text)) {
      const std::string_view base = name.substr(0, name.size() - text.size());
      if (FindColumn(base) != nullptr) return {base, suffix};
    }
  }
  return {name, Suffix::kNone};
}

RotationFormat FormatOf(Group group, const std::optional<EulerSequence>& sequence) {
  RotationFormat format =
      *ParseRotationFormat(Info(group).spelling == "euler" ? "euler:" + sequence->ToString()
                                                           : std::string(Info(group).spelling));
  return format;
}

}  // namespace

const GroupInfo& Info(Group group) {
  return kGroups[static_cast<size_t>(group)];
}

// A printable, bounded version of a user's text for messages.
std::string Quoted(std::string_view text) {
  std::string out = "'";
  const size_t limit = 40;
  for (size_t i = 0; i < text.size() && i < limit; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c != 0x7f) {
      out.push_back(static_cast<char>(c));
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\x%02x", c);
      out += escaped;
    }
  }
  if (text.size() > limit) out += "...";
  out += "'";
  return out;
}

std::string Scientific(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.1e", value);
  return buffer;
}

Layout ParseHeader(const std::vector<Field>& fields, const std::string& source, int line,
                   const PoseReadOptions& options,
                   const std::optional<EulerSequence>& declared_sequence) {
  Layout layout;
  layout.columns = fields.size();
  std::array<Suffix, 3> position_suffix = {};
  std::array<std::array<int, 9>, kGroupCount> group_columns;
  for (auto& columns : group_columns) columns.fill(-1);
  std::array<Suffix, kGroupCount> angle_suffix = {};
  std::array<int, kGroupCount> angle_suffix_column = {};
  std::array<bool, kGroupCount> angle_suffix_seen = {};
  std::unordered_map<std::string, size_t> seen;

  for (size_t i = 0; i < fields.size(); ++i) {
    const std::string written(Trim(FieldValue(fields[i])));
    layout.names.push_back(written);
    const std::string position_text = "column " + std::to_string(i + 1);
    if (written.empty()) {
      throw InputError(source, line, "the header's " + position_text + " has no name",
                       "name every column (" + std::string(kValidColumnsText) + ")");
    }
    const std::string name = Lowercase(written);
    if (const auto [it, inserted] = seen.emplace(name, i); !inserted) {
      throw InputError(source, line,
                       "column " + Quoted(written) + " appears twice (columns " +
                           std::to_string(it->second + 1) + " and " + std::to_string(i + 1) + ")",
                       "keep one of them");
    }
    const auto [base, suffix] = SplitSuffix(name);
    const KnownColumn* column = FindColumn(base);
    if (column == nullptr) {
      std::string problem = "unknown column " + Quoted(written);
      const std::string suggestion = SuggestColumn(name);
      if (!suggestion.empty()) problem += " (did you mean '" + suggestion + "'?)";
      if (fields.size() == 1 && name.find(';') != std::string::npos) {
        throw InputError(source, line, problem, "separate columns with commas, not semicolons");
      }
      throw InputError(source, line, problem,
                       "valid columns are " + std::string(kValidColumnsText));
    }
    const int index = static_cast<int>(i);
    switch (column->role) {
      case Role::kPosition:
        if (suffix == Suffix::kDegree || suffix == Suffix::kRadian) {
          throw InputError(source, line,
                           "column " + Quoted(written) + " has an angle unit but is a position",
                           "use _m or _mm on x, y and z");
        }
        layout.position[column->index] = index;
        position_suffix[column->index] = suffix;
        break;
      case Role::kId:
      case Role::kStamp:
        if (suffix != Suffix::kNone) {
          throw InputError(
              source, line, "column " + Quoted(written) + " cannot have a unit",
              column->role == Role::kStamp ? "name it 'stamp' (always seconds)" : "name it 'id'");
        }
        (column->role == Role::kId ? layout.id : layout.stamp) = index;
        break;
      case Role::kRotation: {
        const size_t g = static_cast<size_t>(column->group);
        if (suffix == Suffix::kMetre || suffix == Suffix::kMillimetre) {
          throw InputError(source, line,
                           "column " + Quoted(written) + " has a length unit but is a rotation",
                           "angles take _deg or _rad");
        }
        if (suffix != Suffix::kNone && !Info(column->group).has_angles) {
          throw InputError(source, line,
                           "column " + Quoted(written) + " cannot have an angle unit: " +
                               std::string(Info(column->group).spelling) +
                               " components are unitless",
                           "name it '" + std::string(column->name) + "'");
        }
        if (angle_suffix_seen[g] && angle_suffix[g] != suffix) {
          throw InputError(source, line,
                           "mixed angle units: column " + Quoted(written) + " and column " +
                               Quoted(layout.names[angle_suffix_column[g]]),
                           "give all angle columns the same suffix (_deg or _rad), or none");
        }
        angle_suffix_seen[g] = true;
        angle_suffix[g] = suffix;
        angle_suffix_column[g] = index;
        group_columns[g][column->index] = index;
        break;
      }
    }
  }

  // Exactly one complete rotation group.
  std::vector<Group> present;
  for (int g = 0; g < kGroupCount; ++g) {
    const auto& columns = group_columns[g];
    if (std::any_of(columns.begin(), columns.end(), [](int c) { return c >= 0; })) {
      present.push_back(static_cast<Group>(g));
    }
  }
  if (present.empty()) {
    throw InputError(source, line, "no rotation columns",
                     "add one rotation group: qw,qx,qy,qz | rx,ry,rz | r11..r33 | a1,a2,a3 | "
                     "roll,pitch,yaw | a,b,c | w,p,r | q1,q2,q3,q4");
  }
  if (present.size() > 1) {
    throw InputError(source, line,
                     "two rotation groups: " + GroupColumnsText(present[0]) + " and " +
                         GroupColumnsText(present[1]),
                     "keep exactly one rotation group per file");
  }
  layout.group = present[0];
  const size_t g = static_cast<size_t>(layout.group);
  std::string missing;
  for (int k = 0; k < Info(layout.group).size; ++k) {
    if (group_columns[g][k] >= 0) continue;
    for (const KnownColumn& column : kKnownColumns) {
      if (column.role == Role::kRotation && column.group == layout.group && column.index == k) {
        if (!missing.empty()) missing += ",";
        missing += column.name;
      }
    }
  }
  if (!missing.empty()) {
    throw InputError(
        source, line,
        "rotation group " + GroupColumnsText(layout.group) + " lacks column(s) " + missing,
        "add the missing column(s)");
  }
  std::copy(group_columns[g].begin(), group_columns[g].end(), layout.rotation.begin());

  // Position: all three, one unit.
  std::string missing_position;
  for (int k = 0; k < 3; ++k) {
    if (layout.position[k] < 0) {
      if (!missing_position.empty()) missing_position += ",";
      missing_position += "xyz"[k];
    }
  }
  if (!missing_position.empty()) {
    throw InputError(source, line, "missing position column(s) " + missing_position,
                     "add x,y,z (optionally x_mm,y_mm,z_mm)");
  }
  for (int k = 1; k < 3; ++k) {
    if (position_suffix[k] != position_suffix[0]) {
      throw InputError(source, line,
                       "mixed length units: column " + Quoted(layout.names[layout.position[0]]) +
                           " and column " + Quoted(layout.names[layout.position[k]]),
                       "give x, y and z the same suffix (_m or _mm), or none");
    }
  }
  switch (position_suffix[0]) {
    case Suffix::kMetre:
      layout.unit = LengthUnit::kMetre;
      layout.unit_named = true;
      break;
    case Suffix::kMillimetre:
      layout.unit = LengthUnit::kMillimetre;
      layout.unit_named = true;
      break;
    default:
      layout.unit = options.units;
      break;
  }

  // Euler sequence: presets fix it; a1,a2,a3 take it from the file's "# euler: SEQ" line or
  // from --euler.
  switch (layout.group) {
    case Group::kEuler:
      layout.sequence = declared_sequence ? declared_sequence : options.euler;
      if (!layout.sequence) {
        throw InputError(source, line, "columns a1,a2,a3 need an Euler sequence",
                         "pass --euler SEQ (e.g. --euler ZYX) or add a line '# euler: ZYX' "
                         "before the header");
      }
      break;
    case Group::kRpy:
    case Group::kKuka:
    case Group::kFanuc: {
      const RotationFormat preset = *ParseRotationFormat(Info(layout.group).spelling);
      layout.sequence = preset.sequence;
      const std::optional<EulerSequence> requested =
          declared_sequence ? declared_sequence : options.euler;
      if (requested && *requested != *layout.sequence) {
        throw InputError(source, line,
                         "Euler sequence " + requested->ToString() + " was requested but the " +
                             std::string(Info(layout.group).spelling) + " columns " +
                             GroupColumnsText(layout.group) + " are always " +
                             layout.sequence->ToString(),
                         "drop --euler, or name the columns a1,a2,a3");
      }
      break;
    }
    default:
      break;
  }
  layout.format = FormatOf(layout.group, layout.sequence);

  // Angle unit: suffix, else the format's own default (kuka, fanuc: degrees), else --degrees.
  if (Info(layout.group).has_angles) {
    switch (angle_suffix[g]) {
      case Suffix::kDegree:
        layout.degrees = true;
        break;
      case Suffix::kRadian:
        layout.degrees = false;
        break;
      default:
        layout.degrees = layout.format.angles_in_degrees || options.degrees;
        break;
    }
  }
  return layout;
}

// "# euler: ZYX" before the header declares the sequence of a1,a2,a3 columns.
std::optional<EulerSequence> EulerDirective(std::string_view comment_line) {
  const std::string_view text = CommentText(comment_line);
  constexpr std::string_view kKey = "euler";
  if (text.size() <= kKey.size() || Lowercase(text.substr(0, kKey.size())) != kKey) {
    return std::nullopt;
  }
  std::string_view rest = Trim(text.substr(kKey.size()));
  if (rest.empty() || rest.front() != ':') return std::nullopt;
  return EulerSequence::Parse(Trim(rest.substr(1)));
}

}  // namespace hecal::io::pose_table_internal
