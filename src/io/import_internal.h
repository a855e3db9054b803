// Internal helpers shared by the `hecal import` readers (not installed): strict number parsing
// that remembers how many digits were printed, pose construction with the checks every importer
// applies, and error reporting.
//
// Rotations go through io::RotationInput (hecal/io/rotation_input.h), the rule every pose reader
// shares: matrices within 1e-6 of SO(3) are projected silently, within the tolerance (1e-3, or
// the printed-digits bound 6·u up to 1e-2) projected with a note, beyond it refused with the
// reason (reflection, scale, coarse digits, not orthonormal); quaternions likewise with 3·u.
// Each importer keeps one RotationInput per output table and puts its Notes() in the table's
// warnings.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/io/pose_table.h"
#include "hecal/io/rotation_input.h"

namespace hecal::io::import_internal {

// Throws hecal::InputError(source, line, problem, fix).
[[noreturn]] void Fail(const std::string& source, int line, const std::string& problem,
                       const std::string& fix);

// A number read from text and the largest error its printed digits can hide.
struct Number {
  double value = 0.0;
  double rounding = 0.0;  // PrintedRounding of the text: 0.5·10^(exponent − fraction digits)
};

// Parses one whole token as a decimal number (optional sign, digits, '.', exponent; also "nan",
// "inf"). nullopt when the token is anything else.
std::optional<Number> ParseNumber(std::string_view token);

// Short text of a number for messages ("3.2e-04").
std::string Scientific(double value);
// `text` in double quotes, shortened to 40 characters, control bytes as '?'.
std::string Quoted(std::string_view text);

// Where a pose came from, for messages: `what` names it ("T1_3", "sample 4 M_eef").
struct Origin {
  std::string source;
  int line = 0;
  std::string what;
};

// A pose from a homogeneous matrix in row-major order: 16 values (4×4, last row must be
// 0 0 0 1 within 1e-9) or 12 values (3×4). Translation is multiplied by `metres_per_unit`.
// `rounding` is the largest rounding bound of the nine rotation entries; the rotation goes
// through `rotations` (its origin.source must be the one `rotations` names).
Pose PoseFromRowMajor(const double* values, int count, double rounding, double metres_per_unit,
                      const Origin& origin, RotationInput* rotations);

// A pose from a rotation matrix (row-major, 9 values) and a translation.
Pose PoseFromRotationAndTranslation(const double* rotation, const double* translation,
                                    double rounding, double metres_per_unit, const Origin& origin,
                                    RotationInput* rotations);

// A pose from a translation and a Hamilton quaternion given as (w, x, y, z); `columns` names the
// four values as the source writes them (for the refusal's fix).
Pose PoseFromQuaternion(const Eigen::Vector3d& translation, const Eigen::Vector4d& wxyz,
                        double rounding, double metres_per_unit, const Origin& origin,
                        std::string_view columns, RotationInput* rotations);

// A pose from a rotation vector (radians; OpenCV's Rodrigues rvec) and a translation.
Pose PoseFromRotationVector(const Eigen::Vector3d& rvec, const Eigen::Vector3d& translation,
                            double metres_per_unit, const Origin& origin);

// Lines of a text with their 1-based numbers; a trailing '\r' is dropped and a leading UTF-8
// byte-order mark skipped.
struct TextLine {
  int number = 0;
  std::string_view text;
};
std::vector<TextLine> SplitLines(std::string_view text);

// True for lines that are empty or only spaces/tabs.
bool IsBlankLine(std::string_view line);
// True for lines whose first non-blank character is '#'.
bool IsCommentLine(std::string_view line);

// Splits a line at runs of spaces, tabs and commas ("1, 2, 3", "1\t2\t3", "1 2 3").
std::vector<std::string_view> SplitTokens(std::string_view line);

// Parses every token of a line as a number; fails (file:line) naming the first bad token.
std::vector<Number> ParseNumbers(const std::vector<std::string_view>& tokens,
                                 const std::string& source, int line);

// A table with the given source and length unit, rows to be filled by the caller.
PoseTable MakeTable(const std::string& source, LengthUnit unit);

// Appends "i" ids ("0", "1", ...) to rows without an id.
void NumberRows(PoseTable* table);

// The file name of a path without directory and extension ("dir/image7.png" → "image7").
std::string FileStem(std::string_view path);

// The common header lines: format and source, the frame written, the convention applied.
std::string RobotFrameNote();
std::string CameraFrameNote();
std::string UnitNote(LengthUnit unit, std::string_view how);

}  // namespace hecal::io::import_internal
