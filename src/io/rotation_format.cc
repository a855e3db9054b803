#include "hecal/io/rotation_format.h"

#include "hecal/io/delimited_text.h"

namespace hecal::io {
namespace {

RotationFormat EulerFormat(std::string_view sequence, std::string preset, bool degrees) {
  RotationFormat format;
  format.kind = RotationFormat::Kind::kEuler;
  format.sequence = EulerSequence::Parse(sequence);
  format.preset = std::move(preset);
  format.angles_in_degrees = degrees;
  return format;
}

}  // namespace

std::vector<std::string> RotationFormat::ColumnNames() const {
  if (preset == "abb") return {"q1", "q2", "q3", "q4"};
  if (preset == "rpy") return {"roll", "pitch", "yaw"};
  if (preset == "kuka") return {"a", "b", "c"};
  if (preset == "fanuc") return {"w", "p", "r"};
  switch (kind) {
    case Kind::kQuaternion:
      return {"qw", "qx", "qy", "qz"};
    case Kind::kRotationVector:
      return {"rx", "ry", "rz"};  // also the ur preset
    case Kind::kMatrix:
      return {"r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33"};
    case Kind::kEuler:
      return {"a1", "a2", "a3"};
  }
  return {};
}

std::string RotationFormat::ToString() const {
  if (!preset.empty()) return preset;
  switch (kind) {
    case Kind::kQuaternion:
      return "quaternion";
    case Kind::kRotationVector:
      return "rotvec";
    case Kind::kMatrix:
      return "matrix";
    case Kind::kEuler:
      return "euler:" + (sequence ? sequence->ToString() : std::string("?"));
  }
  return {};
}

std::optional<RotationFormat> ParseRotationFormat(std::string_view text) {
  constexpr std::string_view kEulerPrefix = "euler:";
  if (text.size() > kEulerPrefix.size() &&
      Lowercase(text.substr(0, kEulerPrefix.size())) == kEulerPrefix) {
    const std::string_view sequence = text.substr(kEulerPrefix.size());
    if (!EulerSequence::Parse(sequence)) return std::nullopt;
    return EulerFormat(sequence, "", false);
  }
  const std::string name = Lowercase(text);
  RotationFormat format;
  if (name == "quaternion") {
    format.kind = RotationFormat::Kind::kQuaternion;
  } else if (name == "rotvec") {
    format.kind = RotationFormat::Kind::kRotationVector;
  } else if (name == "matrix") {
    format.kind = RotationFormat::Kind::kMatrix;
  } else if (name == "rpy") {
    return EulerFormat("xyz", "rpy", false);
  } else if (name == "kuka") {
    return EulerFormat("ZYX", "kuka", true);
  } else if (name == "fanuc") {
    return EulerFormat("xyz", "fanuc", true);
  } else if (name == "abb") {
    format.kind = RotationFormat::Kind::kQuaternion;
    format.preset = "abb";
  } else if (name == "ur") {
    format.kind = RotationFormat::Kind::kRotationVector;
    format.preset = "ur";
  } else {
    return std::nullopt;
  }
  return format;
}

std::string_view RotationFormatSpellings() {
  return "quaternion, rotvec, matrix, euler:SEQ (e.g. euler:ZYX, euler:xyz), rpy, kuka, fanuc, "
         "abb, ur";
}

}  // namespace hecal::io
