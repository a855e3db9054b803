// A report's image thumbnail: vision/thumbnail.h, docs/report.md.
#include "hecal/vision/thumbnail.h"

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "hecal/vision/image_read.h"

namespace hecal::vision {

std::string ThumbnailJpeg(const std::string& path, int max_side) {
  const cv::Mat image = ReadGrayImage(path, 1);
  const double scale =
      std::min(1.0, static_cast<double>(max_side) / std::max(image.cols, image.rows));
  cv::Mat small = image;
  if (scale < 1.0) {
    cv::resize(image, small,
               cv::Size(std::max(1, static_cast<int>(image.cols * scale + 0.5)),
                        std::max(1, static_cast<int>(image.rows * scale + 0.5))),
               0, 0, cv::INTER_AREA);
  }
  std::vector<unsigned char> jpeg;
  cv::imencode(".jpg", small, jpeg, {cv::IMWRITE_JPEG_QUALITY, 80});
  return {jpeg.begin(), jpeg.end()};
}

}  // namespace hecal::vision
