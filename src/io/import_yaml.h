// Internal YAML helpers for the importers (yaml-cpp stays private to hecal_io).
//
// OpenCV FileStorage YAML is not quite YAML 1.2: it starts with "%YAML:1.0" (a directive yaml-cpp
// rejects) and tags matrices "!!opencv-matrix". LoadYaml blanks a leading "%YAML..." directive
// line (keeping line numbers) and yaml-cpp keeps tags on the nodes, where the readers ignore them:
// a matrix is recognised by its shape (a map with rows, cols, data), not by its tag.
//
// Every function here turns yaml-cpp's exceptions into hecal::InputError; GuardYaml does the same
// for a reader's whole traversal, so no yaml-cpp exception escapes an importer.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "import_internal.h"

namespace hecal::io::import_internal {

YAML::Node LoadYaml(std::string_view text, const std::string& source);

// 1-based line of a node; 0 when unknown.
int LineOf(const YAML::Node& node);

// The value of `key` in a map node; nullopt when `map` is not a map or has no such key.
std::optional<YAML::Node> Find(const YAML::Node& map, std::string_view key);

// A scalar number (also YAML's .nan / .inf, which the pose checks then reject).
Number ScalarNumber(const YAML::Node& node, const std::string& source, const std::string& what);
// A non-negative integer scalar no larger than `max`.
long ScalarCount(const YAML::Node& node, const std::string& source, const std::string& what,
                 long max);
// The text of a scalar; fails when the node is not a scalar.
std::string ScalarText(const YAML::Node& node, const std::string& source, const std::string& what);

// A matrix: an !!opencv-matrix map (rows, cols, dt, data), a flat list of numbers (rows = 1), or a
// list of equally long row lists. Values are row-major, each with the rounding bound of its
// printed digits (PrintedRounding).
struct Matrix {
  int rows = 0;
  int cols = 0;
  std::vector<double> values;
  std::vector<double> roundings;
  int line = 0;
};
Matrix ReadMatrix(const YAML::Node& node, const std::string& source, const std::string& what);

// The largest rounding of the rotation entries of a pose matrix: all values of a 3×3, the left
// 3×3 block of a row-major 3×4 or 4×4 (also given flat, 12 or 16 values). The translation's
// digits do not widen the rotation tolerance (rotation_input.h).
double RotationRounding(const Matrix& matrix);

// Runs `body`, turning any yaml-cpp exception into an InputError for `source`.
template <typename Body>
auto GuardYaml(const std::string& source, Body&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const YAML::Exception& e) {
    Fail(source, e.mark.is_null() ? 0 : e.mark.line + 1, "cannot read the YAML: " + e.msg,
         "fix the YAML structure");
  }
}

}  // namespace hecal::io::import_internal
