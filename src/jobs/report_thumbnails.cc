// The image thumbnails of a report page: jobs/report_thumbnails.h, docs/report.md.
#include "hecal/jobs/report_thumbnails.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <opencv2/core/utility.hpp>

#include "hecal/core/error.h"
#include "hecal/vision/thumbnail.h"

namespace hecal::jobs {

std::vector<report::Thumbnail> ReadThumbnails(const std::string& folder,
                                              const std::vector<ReportImage>& images,
                                              const std::string& flag) {
  const size_t n = std::min(images.size(), report::kMaxThumbnails);
  std::vector<std::string> paths(n);
  for (size_t k = 0; k < n; ++k) {
    paths[k] = (std::filesystem::path(folder) / images[k].file).string();
    std::error_code error;
    if (!std::filesystem::is_regular_file(paths[k], error)) {
      throw InputError(
          paths[k], 0,
          "the image of station '" + images[k].id + "' is not in " + flag + " " + folder,
          "give " + flag + " the image folder the result was calibrated from");
    }
  }
  std::vector<report::Thumbnail> thumbnails(n);
  std::vector<std::exception_ptr> errors(n);
  cv::parallel_for_(cv::Range(0, static_cast<int>(n)), [&](const cv::Range& range) {
    for (int k = range.start; k < range.end; ++k) {
      const size_t i = static_cast<size_t>(k);
      try {
        thumbnails[i] = {images[i].id, vision::ThumbnailJpeg(paths[i], report::kThumbnailSide)};
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  });
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  return thumbnails;
}

}  // namespace hecal::jobs
