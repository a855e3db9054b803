// OpenCV's log switched off: see opencv_log.h.
#include "hecal/vision/opencv_log.h"

#include <opencv2/core/utils/logger.hpp>

namespace hecal::vision {

void SilenceOpenCvLog() {
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
}

}  // namespace hecal::vision
