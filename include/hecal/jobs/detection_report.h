// The detect page of the HTML report as a job step (`hecal detect --report FILE`;
// docs/report.md, "The detect page"): the image front end's result (vision/image_set.h) as
// report::DetectionPageInput — per image its detected points, their residuals at its refined PnP
// pose, its RMS and pose, or why it was skipped — with the used images' thumbnails
// (report_thumbnails.h) read from the folder, and the page's text (report/detection_page.h).
// Vision layer only. Errors: those of ReadThumbnails (an image unreadable since detection).
#pragma once

#include <string>

#include "hecal/vision/image_set.h"

namespace hecal::jobs {

// `folder` is the image folder the set was detected in; `intrinsics_source` the camera file given,
// or "" when the set estimated them.
std::string FormatDetectionReport(const vision::ImageSet& set, const std::string& folder,
                                  const std::string& intrinsics_source);

}  // namespace hecal::jobs
