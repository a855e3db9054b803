// How the rotation of a pose is written in a table (docs/conventions.md).
//   quaternion   columns qw,qx,qy,qz (Hamilton)
//   rotvec       columns rx,ry,rz (rotation vector; radians unless --degrees or rx_deg)
//   matrix       columns r11,r12,...,r33 (row-major)
//   euler:SEQ    columns a1,a2,a3 for the sequence SEQ (see geometry/euler.h)
//   presets      rpy   = euler xyz extrinsic, columns roll,pitch,yaw
//                kuka  = euler ZYX intrinsic, columns a,b,c, degrees
//                fanuc = euler xyz extrinsic, columns w,p,r, degrees
//                abb   = quaternion, columns q1,q2,q3,q4 = w,x,y,z
//                ur    = rotation vector, columns rx,ry,rz, radians
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/geometry/euler.h"

namespace hecal::io {

struct RotationFormat {
  enum class Kind { kQuaternion, kRotationVector, kMatrix, kEuler };
  Kind kind = Kind::kQuaternion;
  std::optional<EulerSequence> sequence;  // set iff kind == kEuler
  std::string preset;                     // "" or rpy | kuka | fanuc | abb | ur
  bool angles_in_degrees = false;         // default angle unit of this format (kuka, fanuc)

  // Column names of the rotation group, in order (e.g. {"qw","qx","qy","qz"}, {"a","b","c"}).
  std::vector<std::string> ColumnNames() const;
  // The --to spelling: "quaternion", "rotvec", "matrix", "euler:ZYX", "kuka", ...
  std::string ToString() const;

  friend bool operator==(const RotationFormat&, const RotationFormat&) = default;
};

// Parses the --to / --rotation spelling above; nullopt when unknown. Names are case-insensitive;
// the Euler sequence after "euler:" is not (lowercase = extrinsic, uppercase = intrinsic).
std::optional<RotationFormat> ParseRotationFormat(std::string_view text);

// The accepted spellings, for help texts and error messages.
std::string_view RotationFormatSpellings();

}  // namespace hecal::io
