#include "hecal/io/import_types.h"

#include <charconv>

namespace hecal::io {
namespace {

void AppendNumber(double value, std::string* out) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out->append(buffer, result.ptr);
}

}  // namespace

std::string FormatIntrinsicsYaml(const ImportedIntrinsics& intrinsics,
                                 const std::vector<std::string>& comments, int width, int height) {
  std::string out;
  for (const std::string& comment : comments) out += "# " + comment + "\n";
  const std::pair<const char*, double> values[] = {
      {"fx", intrinsics.fx}, {"fy", intrinsics.fy}, {"cx", intrinsics.cx}, {"cy", intrinsics.cy}};
  for (const auto& [name, value] : values) {
    out += name;
    out += ": ";
    AppendNumber(value, &out);
    out += '\n';
  }
  if (width > 0 && height > 0) {
    out += "width: " + std::to_string(width) + "\nheight: " + std::to_string(height) + "\n";
  }
  out += "distortion:\n  model: plumb_bob\n  coefficients: [";
  for (size_t k = 0; k < intrinsics.distortion.size(); ++k) {
    if (k > 0) out += ", ";
    AppendNumber(intrinsics.distortion[k], &out);
  }
  out += "]\n";
  return out;
}

}  // namespace hecal::io
