// The detect page of the HTML report as a job step: jobs/detection_report.h, docs/report.md.
#include "hecal/jobs/detection_report.h"

#include <vector>

#include "hecal/jobs/report_thumbnails.h"
#include "hecal/report/detection_page.h"

namespace hecal::jobs {

std::string FormatDetectionReport(const vision::ImageSet& set, const std::string& folder,
                                  const std::string& intrinsics_source) {
  report::DetectionPageInput input;
  input.title = folder;
  input.target = vision::Describe(set.target);
  if (!set.board.empty()) {
    Eigen::Vector2d low = set.board[0].position.head<2>(), high = low;
    for (const pose::ObjectPoint& p : set.board) {
      low = low.cwiseMin(p.position.head<2>());
      high = high.cwiseMax(p.position.head<2>());
    }
    input.target_extent << low, high;
  }
  input.camera = set.camera;
  input.camera.width = set.size.width;
  input.camera.height = set.size.height;
  input.intrinsics_source = set.estimated ? "estimated from the images" : intrinsics_source;
  std::vector<ReportImage> used;
  for (const vision::ImageRecord& record : set.images) {
    report::DetectionPageImage image;
    image.id = record.id();
    image.file = record.name;
    image.skipped = record.skipped;
    if (record.used()) {
      image.points_px = vision::PixelsOf(record.detection);
      image.residuals_px = record.pose->residuals_px;
      image.rms_px = record.pose->rms_px;
      image.T_camera_target = record.pose->T_camera_target.matrix();
      used.push_back({image.id, image.file});
    }
    input.images.push_back(std::move(image));
  }
  input.thumbnails = ReadThumbnails(folder, used, "--images");
  return report::FormatDetectionPage(input);
}

}  // namespace hecal::jobs
