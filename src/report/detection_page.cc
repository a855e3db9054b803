// The detect page of the HTML report: detection_page.h, docs/report.md.
#include "hecal/report/detection_page.h"

#include "hecal/report/html_report.h"
#include "hecal/report/json_matrix.h"
#include "hecal/report/result_file.h"

namespace hecal::report {

std::string FormatDetectionPage(const DetectionPageInput& input) {
  using nlohmann::json;
  json per_image = json::array();
  json skipped = json::array();
  for (const DetectionPageImage& image : input.images) {
    if (!image.skipped.empty()) {
      skipped.push_back({{"id", image.id}, {"reason", image.skipped}});
      continue;
    }
    per_image.push_back({{"id", image.id},
                         {"file", image.file},
                         {"rms_px", image.rms_px},
                         {"points_px", JsonPixels(image.points_px, kPointDecimals)},
                         {"residuals_px", JsonPixels(image.residuals_px, kResidualDecimals)},
                         {"T_camera_target", JsonRows(image.T_camera_target)}});
  }
  const pose::CameraModel& k = input.camera;
  json data = {{"kind", "detect"},
               {"title", input.title},
               {"target", input.target},
               {"target_extent", JsonVector(input.target_extent)},
               {"intrinsics",
                {{"fx", k.fx},
                 {"fy", k.fy},
                 {"cx", k.cx},
                 {"cy", k.cy},
                 {"width", k.width},
                 {"height", k.height},
                 {"source", input.intrinsics_source}}},
               {"per_image", per_image},
               {"skipped", skipped}};
  data["thumbnails"] = ThumbnailsJson(input.thumbnails, per_image.size());
  return FormatHtmlPage(std::move(data));
}

}  // namespace hecal::report
