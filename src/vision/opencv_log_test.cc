// SilenceOpenCvLog: OpenCV's log level is silent afterwards, from any level before, and stays so
// when called again.
#include "hecal/vision/opencv_log.h"

#include <gtest/gtest.h>

#include <opencv2/core/utils/logger.hpp>

namespace hecal::vision {
namespace {

TEST(OpenCvLog, SilentAfterwardsFromAVerboseLevel) {
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_VERBOSE);
  SilenceOpenCvLog();
  EXPECT_EQ(cv::utils::logging::getLogLevel(), cv::utils::logging::LOG_LEVEL_SILENT);
  SilenceOpenCvLog();
  EXPECT_EQ(cv::utils::logging::getLogLevel(), cv::utils::logging::LOG_LEVEL_SILENT);
}

}  // namespace
}  // namespace hecal::vision
