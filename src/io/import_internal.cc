#include "import_internal.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <system_error>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"

namespace hecal::io::import_internal {
namespace {

constexpr double kLastRowTolerance = 1e-9;

bool IsDigit(char c) {
  return c >= '0' && c <= '9';
}

bool EqualsIgnoreCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    const char x = (a[i] >= 'A' && a[i] <= 'Z') ? static_cast<char>(a[i] - 'A' + 'a') : a[i];
    if (x != b[i]) return false;
  }
  return true;
}

// Checks the shape of a decimal number: [sign] (digits [. [digits]] | . digits) [e [sign] digits].
bool IsDecimal(std::string_view text) {
  size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  size_t digits = 0;
  while (i < text.size() && IsDigit(text[i])) ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && IsDigit(text[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    size_t exponent_digits = 0;
    while (i < text.size() && IsDigit(text[i])) ++i, ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  return i == text.size();
}

void CheckFinite(const double* values, int count, int columns, const Origin& origin) {
  for (int k = 0; k < count; ++k) {
    if (!std::isfinite(values[k])) {
      Fail(origin.source, origin.line,
           origin.what + " contains a non-finite number (" +
               (std::isnan(values[k]) ? std::string("nan") : std::string("inf")) + " at row " +
               std::to_string(k / columns + 1) + ", column " + std::to_string(k % columns + 1) +
               ")",
           "replace it with a finite value or remove the sample");
    }
  }
}

}  // namespace

void Fail(const std::string& source, int line, const std::string& problem, const std::string& fix) {
  throw InputError(source, line, problem, fix);
}

std::optional<Number> ParseNumber(std::string_view token) {
  std::string_view body = token;
  bool negative = false;
  if (!body.empty() && (body.front() == '+' || body.front() == '-')) {
    negative = body.front() == '-';
    body.remove_prefix(1);
  }
  if (EqualsIgnoreCase(body, "nan")) {
    return Number{std::numeric_limits<double>::quiet_NaN(), 0.0};
  }
  if (EqualsIgnoreCase(body, "inf") || EqualsIgnoreCase(body, "infinity")) {
    const double inf = std::numeric_limits<double>::infinity();
    return Number{negative ? -inf : inf, 0.0};
  }
  if (!IsDecimal(token)) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(body.data(), body.data() + body.size(), value);
  if (error == std::errc::result_out_of_range) {
    // Overflow or underflow: strtod gives ±HUGE_VAL or 0 (hecal never changes the C locale).
    const std::string copy(body);
    value = std::strtod(copy.c_str(), nullptr);
  } else if (error != std::errc() || end != body.data() + body.size()) {
    return std::nullopt;
  }
  return Number{negative ? -value : value, PrintedRounding(token)};
}

std::string Scientific(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.1e", value);
  return buffer;
}

std::string Quoted(std::string_view text) {
  std::string out = "\"";
  const size_t limit = 40;
  for (size_t i = 0; i < text.size() && i < limit; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    out += (c < 0x20 || c == 0x7f) ? '?' : static_cast<char>(c);
  }
  if (text.size() > limit) out += "...";
  out += '"';
  return out;
}

Pose PoseFromRowMajor(const double* values, int count, double rounding, double metres_per_unit,
                      const Origin& origin, RotationInput* rotations) {
  CheckFinite(values, count, 4, origin);
  if (count == 16) {
    const double* last = values + 12;
    const bool last_row_ok =
        std::abs(last[0]) <= kLastRowTolerance && std::abs(last[1]) <= kLastRowTolerance &&
        std::abs(last[2]) <= kLastRowTolerance && std::abs(last[3] - 1.0) <= kLastRowTolerance;
    if (!last_row_ok) {
      const bool looks_transposed =
          std::abs(values[3]) <= kLastRowTolerance && std::abs(values[7]) <= kLastRowTolerance &&
          std::abs(values[11]) <= kLastRowTolerance && std::abs(last[3] - 1.0) <= kLastRowTolerance;
      char row[128];
      std::snprintf(row, sizeof(row), "(%.6g %.6g %.6g %.6g)", last[0], last[1], last[2], last[3]);
      Fail(origin.source, origin.line,
           origin.what + ": the last row of the 4x4 matrix is " + row + ", not (0 0 0 1)",
           looks_transposed ? "the matrix looks column-major (translation in the last row); "
                              "write it row-major (r11 r12 r13 tx r21 ... 0 0 0 1)"
                            : "write a homogeneous transform, row-major, last row 0 0 0 1");
    }
  } else if (count != 12) {
    Fail(origin.source, origin.line,
         origin.what + " has " + std::to_string(count) + " numbers, not 16 (4x4) or 12 (3x4)",
         "write the pose as a row-major 4x4 or 3x4 matrix");
  }
  const double rotation[9] = {values[0], values[1], values[2], values[4], values[5],
                              values[6], values[8], values[9], values[10]};
  const double translation[3] = {values[3], values[7], values[11]};
  return PoseFromRotationAndTranslation(rotation, translation, rounding, metres_per_unit, origin,
                                        rotations);
}

Pose PoseFromRotationAndTranslation(const double* rotation, const double* translation,
                                    double rounding, double metres_per_unit, const Origin& origin,
                                    RotationInput* rotations) {
  CheckFinite(rotation, 9, 3, origin);
  CheckFinite(translation, 3, 3, origin);
  Eigen::Matrix3d R;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) R(i, j) = rotation[3 * i + j];
  }
  Pose pose = Pose::Identity();
  pose.linear() = rotations->Matrix(R, rounding, RotationPlace{origin.line, origin.what});
  pose.translation() =
      Eigen::Vector3d(translation[0], translation[1], translation[2]) * metres_per_unit;
  return pose;
}

Pose PoseFromQuaternion(const Eigen::Vector3d& translation, const Eigen::Vector4d& wxyz,
                        double rounding, double metres_per_unit, const Origin& origin,
                        std::string_view columns, RotationInput* rotations) {
  const double values[7] = {translation[0], translation[1], translation[2], wxyz[0],
                            wxyz[1],        wxyz[2],        wxyz[3]};
  for (int k = 0; k < 7; ++k) {
    if (!std::isfinite(values[k])) {
      Fail(origin.source, origin.line,
           origin.what + " contains a non-finite number (" +
               std::string(k < 3 ? "translation" : "quaternion") + ")",
           "replace it with a finite value or remove the sample");
    }
  }
  Pose pose = Pose::Identity();
  pose.linear() =
      rotations->Quaternion(wxyz, rounding, RotationPlace{origin.line, origin.what}, columns);
  pose.translation() = translation * metres_per_unit;
  return pose;
}

Pose PoseFromRotationVector(const Eigen::Vector3d& rvec, const Eigen::Vector3d& translation,
                            double metres_per_unit, const Origin& origin) {
  if (!rvec.allFinite() || !translation.allFinite()) {
    Fail(origin.source, origin.line, origin.what + " contains a non-finite number",
         "replace it with a finite value or remove the sample");
  }
  Pose pose = Pose::Identity();
  pose.linear() = so3::Exp(rvec);
  pose.translation() = translation * metres_per_unit;
  return pose;
}

std::vector<TextLine> SplitLines(std::string_view text) {
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<TextLine> lines;
  int number = 0;
  size_t begin = 0;
  while (begin <= text.size()) {
    const size_t end = text.find('\n', begin);
    std::string_view line =
        text.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++number;
    if (end == std::string_view::npos) {
      if (!line.empty()) lines.push_back({number, line});
      break;
    }
    lines.push_back({number, line});
    begin = end + 1;
  }
  return lines;
}

bool IsBlankLine(std::string_view line) {
  return line.find_first_not_of(" \t\r\f\v") == std::string_view::npos;
}

bool IsCommentLine(std::string_view line) {
  const size_t first = line.find_first_not_of(" \t");
  return first != std::string_view::npos && line[first] == '#';
}

std::vector<std::string_view> SplitTokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  const auto is_separator = [](char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r'; };
  while (i < line.size()) {
    while (i < line.size() && is_separator(line[i])) ++i;
    const size_t begin = i;
    while (i < line.size() && !is_separator(line[i])) ++i;
    if (i > begin) tokens.push_back(line.substr(begin, i - begin));
  }
  return tokens;
}

std::vector<Number> ParseNumbers(const std::vector<std::string_view>& tokens,
                                 const std::string& source, int line) {
  std::vector<Number> numbers;
  numbers.reserve(tokens.size());
  for (size_t k = 0; k < tokens.size(); ++k) {
    const std::optional<Number> number = ParseNumber(tokens[k]);
    if (!number) {
      Fail(source, line,
           "field " + std::to_string(k + 1) + " (" + Quoted(tokens[k]) + ") is not a number",
           "write plain decimal numbers with '.' as the decimal separator");
    }
    numbers.push_back(*number);
  }
  return numbers;
}

PoseTable MakeTable(const std::string& source, LengthUnit unit) {
  PoseTable table;
  table.source = source;
  table.unit = unit;
  return table;
}

void NumberRows(PoseTable* table) {
  for (size_t i = 0; i < table->rows.size(); ++i) {
    if (!table->rows[i].id) table->rows[i].id = std::to_string(i);
  }
}

std::string FileStem(std::string_view path) {
  const size_t slash = path.find_last_of("/\\");
  if (slash != std::string_view::npos) path.remove_prefix(slash + 1);
  const size_t dot = path.find_last_of('.');
  if (dot != std::string_view::npos && dot > 0) path = path.substr(0, dot);
  return std::string(path);
}

std::string RobotFrameNote() {
  return "poses: T_base_gripper, the gripper (flange/tool) pose in the robot base frame";
}

std::string CameraFrameNote() {
  return "poses: T_camera_target, the target pose in the camera frame";
}

std::string UnitNote(LengthUnit unit, std::string_view how) {
  return "units: lengths in " + std::string(UnitName(unit)) + " (" + std::string(how) +
         "); rotations as Hamilton unit quaternions qw,qx,qy,qz";
}

}  // namespace hecal::io::import_internal
