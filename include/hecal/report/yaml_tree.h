// A JSON tree as YAML text, the YAML form of every hecal result file (docs/result-file.md):
// objects as block maps in the tree's key order, numeric arrays (vectors, matrix rows) as flow
// sequences, doubles with 17 significant digits (they read back to the same double).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace hecal::report {

// The document with a final newline.
std::string YamlText(const nlohmann::json& root);

}  // namespace hecal::report
