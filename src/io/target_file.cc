#include "hecal/io/target_file.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "closest_name.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/units.h"
#include "import_yaml.h"
#include "yaml_map.h"

namespace hecal::io {
namespace {

using import_internal::Fail;
using import_internal::LineOf;
using pose::TargetField;

// What each field means, for "missing key" messages.
std::string_view Meaning(TargetField field) {
  switch (field) {
    case TargetField::kCols:
      return "the number of points, squares or markers along x";
    case TargetField::kRows:
      return "the number of points, squares or markers along y";
    case TargetField::kSquare:
      return "the square side, or the circle pitch";
    case TargetField::kMarker:
      return "the marker side";
    case TargetField::kSpacing:
      return "the gap between neighbouring markers";
    case TargetField::kDictionary:
      return "the ArUco dictionary, e.g. DICT_5X5_250";
    case TargetField::kFamily:
      return "the AprilTag family, e.g. tag36h11";
    case TargetField::kFirstId:
      return "the id of the top-left marker";
    case TargetField::kId:
      return "the id of the tag";
    case TargetField::kSize:
      return "the side of the tag's black square";
  }
  return "";
}

// Lengths a printed target plausibly has, in metres: at least 1 mm, less than 1 m. Outside, the
// unit is the likely mistake (docs/targets.md, "Units").
constexpr double kShortestLength = 1e-3;
constexpr double kLongestLength = 1.0;

// "15 m", "0.015 mm": a value as written in the file, with its unit.
std::string Written(double value, LengthUnit unit) {
  std::ostringstream text;
  text << value << " " << UnitName(unit);
  return text.str();
}

// Refuses a length whose unit is most likely wrong: ≥ 1 m when no unit was given (millimetres
// written without `units: mm`), < 1 mm with `units: mm` (metres marked as millimetres). An
// explicit `units: m` is taken at its word.
void CheckPlausibleLength(double written, std::optional<LengthUnit> unit, const std::string& key,
                          const std::string& source, int line) {
  if (!(written > 0.0) || !std::isfinite(written)) return;  // CheckTarget says what is wrong
  const std::string what = key == "size" ? "tag size" : "target " + key;
  if (!unit && written >= kLongestLength) {
    Fail(source, line,
         key + " " + Written(written, LengthUnit::kMetre) + " is not a plausible " + what,
         "if the lengths are in millimetres add `units: mm`; if the target really is that large, "
         "add `units: m`");
  }
  if (unit == LengthUnit::kMillimetre && written * MetresPer(*unit) < kShortestLength) {
    Fail(source, line,
         key + " " + Written(written, *unit) + " is not a plausible " + what +
             ": it looks like metres",
         "remove `units: mm` (the lengths are then in metres)");
  }
}

std::vector<std::string_view> KnownKeys() {
  std::vector<std::string_view> keys = {"type", "units"};
  for (const TargetField field : pose::TargetFields()) keys.push_back(pose::TargetFieldName(field));
  return keys;
}

std::string Join(const std::vector<std::string_view>& names) {
  std::string text;
  for (const std::string_view name : names) {
    if (!text.empty()) text += ", ";
    text += name;
  }
  return text;
}

std::vector<std::string_view> Names(std::span<const pose::MarkerDictionary> list) {
  std::vector<std::string_view> names;
  for (const pose::MarkerDictionary& entry : list) names.push_back(entry.name);
  return names;
}

// The field a type uses for what `field` means on other types: a single tag's side is `size` and
// its id `id`, a grid's `marker` and `first_id`.
std::optional<TargetField> SameMeaning(pose::TargetType type, TargetField field) {
  const bool tag = pose::IsSingleTag(type);
  if (field == TargetField::kMarker && tag) return TargetField::kSize;
  if (field == TargetField::kFirstId && tag) return TargetField::kId;
  if (field == TargetField::kSize && !tag) return TargetField::kMarker;
  if (field == TargetField::kId && !tag) return TargetField::kFirstId;
  return std::nullopt;
}

// The types that use a field, for "does not apply" messages.
std::string TypesUsing(TargetField field) {
  std::vector<std::string_view> types;
  for (const pose::TargetType type : pose::TargetTypes()) {
    if (pose::TargetFieldUse(type, field) != pose::FieldUse::kUnused) {
      types.push_back(pose::TargetTypeName(type));
    }
  }
  return Join(types);
}

// Counts and ids: whole numbers; CheckTarget judges the range (this bound only keeps them ints).
int ReadWholeNumber(const YAML::Node& node, const std::string& source, const std::string& key) {
  constexpr long kLargest = 1'000'000'000;
  return static_cast<int>(import_internal::ScalarCount(node, source, key, kLargest));
}

pose::TargetSpec ParseTarget(const YAML::Node& root, const std::string& source) {
  if (!root.IsDefined() || root.IsNull()) {
    Fail(source, 0, "the target file is empty",
         "describe the target: type, cols, rows and its lengths (see docs/targets.md)");
  }
  if (!root.IsMap()) {
    Fail(source, LineOf(root), "the target file is not a map of 'key: value' lines",
         "write one 'key: value' per line (see docs/targets.md)");
  }
  const internal::YamlMap entries = internal::ReadYamlMap(root, source);
  const std::vector<std::string_view> known = KnownKeys();
  internal::RejectUnknownKeys(entries, known, source, "");

  std::vector<std::string_view> type_names;
  for (const pose::TargetType type : pose::TargetTypes()) {
    type_names.push_back(pose::TargetTypeName(type));
  }
  const std::optional<YAML::Node> type_node = entries.Find("type");
  if (!type_node) {
    Fail(source, 0, "the target file has no 'type'", "add type: one of " + Join(type_names));
  }
  const int type_line = entries.Line("type");
  const std::string type_text = import_internal::ScalarText(*type_node, source, "type");
  const std::optional<pose::TargetType> type = pose::ParseTargetType(type_text);
  if (!type) {
    Fail(source, type_line,
         "unknown target type " + import_internal::Quoted(type_text) +
             internal::DidYouMean(type_text, type_names),
         "use one of " + Join(type_names));
  }

  std::optional<LengthUnit> unit;  // nullopt: not given, metres
  if (const std::optional<YAML::Node> units = entries.Find("units")) {
    const std::string text = import_internal::ScalarText(*units, source, "units");
    unit = ParseLengthUnit(text);
    if (!unit) {
      Fail(source, entries.Line("units"), "units is " + import_internal::Quoted(text),
           "write units: m or units: mm");
    }
  }
  const double metres_per_unit = MetresPer(unit.value_or(LengthUnit::kMetre));
  // A length in metres, its unit checked for plausibility.
  const auto length = [&](const YAML::Node& node, const std::string& key) {
    const double written = import_internal::ScalarNumber(node, source, key).value;
    CheckPlausibleLength(written, unit, key, source, entries.Line(key));
    return written * metres_per_unit;
  };

  // Keys the type does not use first (a grid's name for a single tag's key is the likelier
  // mistake than the key's absence), then the keys it lacks, then the values.
  for (const TargetField field : pose::TargetFields()) {
    const std::string key(pose::TargetFieldName(field));
    if (!entries.Has(key) || pose::TargetFieldUse(*type, field) != pose::FieldUse::kUnused) {
      continue;
    }
    const std::optional<TargetField> same = SameMeaning(*type, field);
    const std::string fix =
        same && pose::TargetFieldUse(*type, *same) != pose::FieldUse::kUnused
            ? type_text + " targets call it '" + std::string(pose::TargetFieldName(*same)) +
                  "': rename the key"
            : "remove it, or use a type that has it (" + TypesUsing(field) + ")";
    Fail(source, entries.Line(key), "'" + key + "' does not apply to " + type_text + " targets",
         fix);
  }
  for (const TargetField field : pose::TargetFields()) {
    const std::string key(pose::TargetFieldName(field));
    if (!entries.Has(key) && pose::TargetFieldUse(*type, field) == pose::FieldUse::kRequired) {
      Fail(source, type_line,
           type_text + " targets need '" + key + "' (" + std::string(Meaning(field)) +
               "), which the file lacks",
           "add " + key + ": ... (see docs/targets.md)");
    }
  }
  pose::TargetSpec spec;
  spec.type = *type;
  for (const TargetField field : pose::TargetFields()) {
    const std::string key(pose::TargetFieldName(field));
    const std::optional<YAML::Node> node = entries.Find(key);
    if (!node) continue;
    switch (field) {
      case TargetField::kCols:
        spec.cols = ReadWholeNumber(*node, source, key);
        break;
      case TargetField::kRows:
        spec.rows = ReadWholeNumber(*node, source, key);
        break;
      case TargetField::kFirstId:
        spec.first_id = ReadWholeNumber(*node, source, key);
        break;
      case TargetField::kId:
        spec.id = ReadWholeNumber(*node, source, key);
        break;
      case TargetField::kSquare:
        spec.square = length(*node, key);
        break;
      case TargetField::kMarker:
        spec.marker = length(*node, key);
        break;
      case TargetField::kSpacing:
        spec.spacing = length(*node, key);
        break;
      case TargetField::kSize:
        spec.size = length(*node, key);
        break;
      case TargetField::kDictionary:
        spec.dictionary = import_internal::ScalarText(*node, source, key);
        break;
      case TargetField::kFamily:
        spec.family = import_internal::ScalarText(*node, source, key);
        break;
    }
  }

  if (const std::optional<pose::TargetProblem> problem = pose::CheckTarget(spec)) {
    const std::string key(pose::TargetFieldName(problem->field));
    std::string text = problem->problem;
    if (problem->field == TargetField::kDictionary || problem->field == TargetField::kFamily) {
      const bool aruco = problem->field == TargetField::kDictionary;
      const std::vector<std::string_view> names =
          Names(aruco ? pose::ArucoDictionaries() : pose::AprilTagFamilies());
      const std::string& name = aruco ? spec.dictionary : spec.family;
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        text += internal::DidYouMean(name, names);
      }
    }
    Fail(source, entries.Has(key) ? entries.Line(key) : type_line, text, problem->fix);
  }
  return spec;
}

}  // namespace

pose::TargetSpec ParseTargetYaml(std::string_view text, const std::string& source) {
  return import_internal::GuardYaml(
      source, [&] { return ParseTarget(import_internal::LoadYaml(text, source), source); });
}

pose::TargetSpec ReadTargetFile(const std::string& path) {
  return ParseTargetYaml(ReadFile(path), path);
}

}  // namespace hecal::io
