#include "hecal/report/yaml_tree.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>

namespace hecal::report {
namespace {

using nlohmann::json;

void EmitYaml(const json& value, YAML::Emitter& out) {
  if (value.is_object()) {
    out << YAML::BeginMap;
    for (const auto& [key, item] : value.items()) {
      out << YAML::Key << key << YAML::Value;
      EmitYaml(item, out);
    }
    out << YAML::EndMap;
  } else if (value.is_array()) {
    // Numeric rows (matrices, vectors) read best as flow sequences.
    const bool numeric =
        std::all_of(value.begin(), value.end(), [](const json& item) { return item.is_number(); });
    if (numeric) out << YAML::Flow;
    out << YAML::BeginSeq;
    for (const json& item : value) EmitYaml(item, out);
    out << YAML::EndSeq;
  } else if (value.is_string()) {
    out << value.get<std::string>();
  } else if (value.is_boolean()) {
    out << value.get<bool>();
  } else if (value.is_number_integer()) {
    out << value.get<long long>();
  } else if (value.is_number()) {
    out << YAML::Precision(17) << value.get<double>();
  } else {
    out << YAML::Null;
  }
}

}  // namespace

std::string YamlText(const json& root) {
  YAML::Emitter out;
  EmitYaml(root, out);
  return std::string(out.c_str()) + "\n";
}

}  // namespace hecal::report
