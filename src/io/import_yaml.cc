#include "import_yaml.h"

#include <algorithm>
#include <cctype>
#include <limits>

#include "hecal/io/delimited_text.h"

namespace hecal::io::import_internal {
namespace {

// Largest matrix the importers accept (a 4×4 pose is 16 values; this only bounds allocation).
constexpr long kMaxMatrixValues = 1 << 16;

std::string TrimCopy(std::string_view text) {
  const size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string_view::npos) return {};
  const size_t end = text.find_last_not_of(" \t\r\n");
  return std::string(text.substr(begin, end - begin + 1));
}

}  // namespace

YAML::Node LoadYaml(std::string_view text, const std::string& source) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  // OpenCV's "%YAML:1.0" (and any leading %YAML directive): blank it, keep the line count.
  std::string copy;
  if (text.substr(0, 5) == "%YAML") {
    const size_t end = text.find('\n');
    copy = "#";
    if (end != std::string_view::npos) copy.append(text.substr(end));
  } else {
    copy.assign(text);
  }
  try {
    return YAML::Load(copy);
  } catch (const YAML::Exception& e) {
    Fail(source, e.mark.is_null() ? 0 : e.mark.line + 1, "not valid YAML: " + e.msg,
         "fix the YAML syntax (OpenCV FileStorage files may start with %YAML:1.0)");
  }
}

int LineOf(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

std::optional<YAML::Node> Find(const YAML::Node& map, std::string_view key) {
  if (!map.IsDefined() || !map.IsMap()) return std::nullopt;
  for (auto it = map.begin(); it != map.end(); ++it) {
    if (it->first.IsScalar() && it->first.Scalar() == key) return it->second;
  }
  return std::nullopt;
}

std::string ScalarText(const YAML::Node& node, const std::string& source, const std::string& what) {
  if (!node.IsDefined() || !node.IsScalar()) {
    Fail(source, LineOf(node), what + " is not a single value", "write it as a plain scalar");
  }
  return node.Scalar();
}

Number ScalarNumber(const YAML::Node& node, const std::string& source, const std::string& what) {
  if (!node.IsDefined() || !node.IsScalar()) {
    Fail(source, LineOf(node),
         what + " is not a number (found a " +
             (node.IsSequence() ? "list"
              : node.IsMap()    ? "map"
                                : "null") +
             ")",
         "write a plain number");
  }
  const std::string text = TrimCopy(node.Scalar());
  const std::string lower = Lowercase(text);
  if (lower == ".nan") return Number{std::numeric_limits<double>::quiet_NaN(), 0.0};
  if (lower == ".inf" || lower == "+.inf") {
    return Number{std::numeric_limits<double>::infinity(), 0.0};
  }
  if (lower == "-.inf") return Number{-std::numeric_limits<double>::infinity(), 0.0};
  const std::optional<Number> number = ParseNumber(text);
  if (!number) {
    Fail(source, LineOf(node), what + " is " + Quoted(text) + ", not a number",
         "write a plain decimal number with '.' as the decimal separator");
  }
  return *number;
}

long ScalarCount(const YAML::Node& node, const std::string& source, const std::string& what,
                 long max) {
  const Number number = ScalarNumber(node, source, what);
  if (!(number.value >= 0.0) || number.value > static_cast<double>(max) ||
      number.value != static_cast<double>(static_cast<long>(number.value))) {
    Fail(source, LineOf(node),
         what + " is " + Quoted(node.Scalar()) + ", not a whole number between 0 and " +
             std::to_string(max),
         "write a whole number");
  }
  return static_cast<long>(number.value);
}

Matrix ReadMatrix(const YAML::Node& node, const std::string& source, const std::string& what) {
  Matrix matrix;
  matrix.line = LineOf(node);
  const auto add = [&](const YAML::Node& value, const std::string& name) {
    const Number number = ScalarNumber(value, source, name);
    matrix.values.push_back(number.value);
    matrix.roundings.push_back(number.rounding);
  };
  if (node.IsDefined() && node.IsMap()) {
    const std::optional<YAML::Node> rows = Find(node, "rows");
    const std::optional<YAML::Node> cols = Find(node, "cols");
    const std::optional<YAML::Node> data = Find(node, "data");
    if (!rows || !cols || !data) {
      Fail(source, matrix.line,
           what + " is a map without rows, cols and data (not an !!opencv-matrix)",
           "write it as an !!opencv-matrix {rows, cols, dt, data} or a list of numbers");
    }
    matrix.rows = static_cast<int>(ScalarCount(*rows, source, what + " rows", 4096));
    matrix.cols = static_cast<int>(ScalarCount(*cols, source, what + " cols", 4096));
    const long expected = static_cast<long>(matrix.rows) * matrix.cols;
    if (expected > kMaxMatrixValues) {
      Fail(source, matrix.line, what + " is too large (" + std::to_string(expected) + " values)",
           "hecal reads poses: 3x1, 3x3, 3x4 or 4x4 matrices");
    }
    if (const std::optional<YAML::Node> dt = Find(node, "dt")) {
      const std::string type = ScalarText(*dt, source, what + " dt");
      if (type != "d" && type != "f") {
        Fail(source, LineOf(*dt), what + " has dt " + Quoted(type) + "; hecal reads d or f",
             "store the matrix as floating point (CV_64F or CV_32F)");
      }
    }
    const YAML::Node& values = *data;
    if (!values.IsSequence()) {
      Fail(source, LineOf(values), what + " data is not a list", "write data: [ ... ]");
    }
    if (static_cast<long>(values.size()) != expected) {
      Fail(source, LineOf(values),
           what + " has " + std::to_string(values.size()) + " data values but rows x cols = " +
               std::to_string(matrix.rows) + " x " + std::to_string(matrix.cols),
           "make data hold rows*cols values");
    }
    matrix.values.reserve(static_cast<size_t>(expected));
    for (size_t k = 0; k < values.size(); ++k) {
      add(values[k], what + " data[" + std::to_string(k) + "]");
    }
    return matrix;
  }
  if (node.IsDefined() && node.IsSequence()) {
    if (static_cast<long>(node.size()) > kMaxMatrixValues) {
      Fail(source, matrix.line, what + " is too large", "hecal reads 3x1 to 4x4 matrices");
    }
    const bool nested = node.size() > 0 && node[0].IsSequence();
    if (!nested) {
      matrix.rows = 1;
      matrix.cols = static_cast<int>(node.size());
      for (size_t k = 0; k < node.size(); ++k) add(node[k], what + "[" + std::to_string(k) + "]");
      return matrix;
    }
    matrix.rows = static_cast<int>(node.size());
    for (size_t i = 0; i < node.size(); ++i) {
      const YAML::Node row = node[i];
      if (!row.IsSequence()) {
        Fail(source, LineOf(row), what + " row " + std::to_string(i) + " is not a list",
             "write every row as a list of numbers");
      }
      if (i == 0) matrix.cols = static_cast<int>(row.size());
      if (static_cast<int>(row.size()) != matrix.cols ||
          static_cast<long>(matrix.rows) * matrix.cols > kMaxMatrixValues) {
        Fail(source, LineOf(row),
             what + " row " + std::to_string(i) + " has " + std::to_string(row.size()) +
                 " values, row 0 has " + std::to_string(matrix.cols),
             "give every row the same number of values");
      }
      for (size_t j = 0; j < row.size(); ++j) {
        add(row[j], what + "[" + std::to_string(i) + "][" + std::to_string(j) + "]");
      }
    }
    return matrix;
  }
  Fail(source, matrix.line, what + " is not a matrix",
       "write it as an !!opencv-matrix {rows, cols, dt, data} or a list of numbers");
}

double RotationRounding(const Matrix& matrix) {
  const size_t count = matrix.roundings.size();
  double rounding = 0.0;
  for (size_t k = 0; k < count; ++k) {
    if (count == 9 || (k < 12 && k % 4 != 3)) rounding = std::max(rounding, matrix.roundings[k]);
  }
  return rounding;
}

}  // namespace hecal::io::import_internal
