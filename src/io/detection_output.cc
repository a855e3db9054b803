// The files a target detection writes: see detection_output.h.
#include "hecal/io/detection_output.h"

#include <filesystem>

#include "hecal/io/delimited_text.h"

namespace hecal::io {

std::string FormatDetectedPoints(const std::vector<DetectedPoint>& points) {
  std::string text =
      "# hecal detect: detected target points, pixels (origin at the centre of the top-left "
      "pixel)\nid,point_id,u,v\n";
  for (const DetectedPoint& point : points) {
    text += QuoteField(point.image);
    text += ',';
    text += std::to_string(point.point_id);
    text += ',';
    AppendDouble(point.pixel.x(), &text);
    text += ',';
    AppendDouble(point.pixel.y(), &text);
    text += '\n';
  }
  return text;
}

DetectionOutputPaths DetectionCompanionPaths(const std::string& output) {
  const std::string stem = std::filesystem::path(output).replace_extension().string();
  return {stem + ".points.csv", stem + ".camera.yaml"};
}

}  // namespace hecal::io
