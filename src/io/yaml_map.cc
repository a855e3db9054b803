#include "yaml_map.h"

#include <algorithm>

#include "closest_name.h"
#include "import_internal.h"
#include "import_yaml.h"

namespace hecal::io::internal {

std::optional<YAML::Node> YamlMap::Find(const std::string& key) const {
  const auto it = nodes.find(key);
  return it == nodes.end() ? std::nullopt : std::optional<YAML::Node>(it->second);
}

int YamlMap::Line(const std::string& key) const {
  const auto it = lines.find(key);
  return it == lines.end() ? 0 : it->second;
}

YamlMap ReadYamlMap(const YAML::Node& map, const std::string& source) {
  YamlMap entries;
  for (auto it = map.begin(); it != map.end(); ++it) {
    const int line = import_internal::LineOf(it->first);
    if (!it->first.IsScalar()) {
      import_internal::Fail(source, line, "a key is not a plain name",
                            "write every key as a plain name followed by ':'");
    }
    const std::string key = it->first.Scalar();
    if (!entries.nodes.emplace(key, it->second).second) {
      import_internal::Fail(source, line,
                            "key '" + key + "' is given twice (first on line " +
                                std::to_string(entries.Line(key)) + ")",
                            "keep one of them");
    }
    entries.lines[key] = line;
    entries.keys.push_back(key);
  }
  return entries;
}

void RejectUnknownKeys(const YamlMap& map, std::span<const std::string_view> known,
                       const std::string& source, const std::string& where) {
  for (const std::string& key : map.keys) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string names;
    for (const std::string_view name : known) {
      if (!names.empty()) names += ", ";
      names += name;
    }
    import_internal::Fail(
        source, map.Line(key),
        "unknown key " + import_internal::Quoted(key) + where + DidYouMean(key, known),
        "remove it or correct its name; the keys here are " + names);
  }
}

}  // namespace hecal::io::internal
