// Internal: the entries of a YAML map read strictly, for hecal's own key: value files
// (target.yaml, camera.yaml). Keys must be plain scalars and appear once; unknown keys are
// reported with the nearest known one. Errors are hecal::InputError with the key's line.
#pragma once

#include <yaml-cpp/yaml.h>

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hecal::io::internal {

struct YamlMap {
  std::vector<std::string> keys;  // in file order
  std::map<std::string, YAML::Node> nodes;
  std::map<std::string, int> lines;  // 1-based line of each key

  std::optional<YAML::Node> Find(const std::string& key) const;
  bool Has(const std::string& key) const { return nodes.count(key) > 0; }
  int Line(const std::string& key) const;  // 0 for an absent key
};

// Fails when a key is not a scalar or is given twice.
YamlMap ReadYamlMap(const YAML::Node& map, const std::string& source);

// Fails on the first key (in file order) outside `known`, suggesting the nearest known key;
// `where` qualifies the message (e.g. " in distortion").
void RejectUnknownKeys(const YamlMap& map, std::span<const std::string_view> known,
                       const std::string& source, const std::string& where);

}  // namespace hecal::io::internal
