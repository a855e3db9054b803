#include "hecal/io/target_file.h"

#include <algorithm>
#include <optional>
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
  }
  return "";
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

pose::TargetSpec Parse(const YAML::Node& root, const std::string& source) {
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

  double metres_per_unit = 1.0;
  if (const std::optional<YAML::Node> units = entries.Find("units")) {
    const std::string text = import_internal::ScalarText(*units, source, "units");
    const std::optional<LengthUnit> unit = ParseLengthUnit(text);
    if (!unit) {
      Fail(source, entries.Line("units"), "units is " + import_internal::Quoted(text),
           "write units: m or units: mm");
    }
    metres_per_unit = MetresPer(*unit);
  }

  pose::TargetSpec spec;
  spec.type = *type;
  for (const TargetField field : pose::TargetFields()) {
    const std::string key(pose::TargetFieldName(field));
    const std::optional<YAML::Node> node = entries.Find(key);
    const pose::FieldUse use = pose::TargetFieldUse(*type, field);
    if (!node) {
      if (use == pose::FieldUse::kRequired) {
        Fail(source, type_line,
             type_text + " targets need '" + key + "' (" + std::string(Meaning(field)) +
                 "), which the file lacks",
             "add " + key + ": ... (see docs/targets.md)");
      }
      continue;
    }
    if (use == pose::FieldUse::kUnused) {
      Fail(source, entries.Line(key), "'" + key + "' does not apply to " + type_text + " targets",
           "remove it, or use a type that has it (" + TypesUsing(field) + ")");
    }
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
      case TargetField::kSquare:
        spec.square = import_internal::ScalarNumber(*node, source, key).value * metres_per_unit;
        break;
      case TargetField::kMarker:
        spec.marker = import_internal::ScalarNumber(*node, source, key).value * metres_per_unit;
        break;
      case TargetField::kSpacing:
        spec.spacing = import_internal::ScalarNumber(*node, source, key).value * metres_per_unit;
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
      source, [&] { return Parse(import_internal::LoadYaml(text, source), source); });
}

pose::TargetSpec ReadTargetFile(const std::string& path) {
  return ParseTargetYaml(ReadFile(path), path);
}

}  // namespace hecal::io
