// libFuzzer target for the image loader's own part (vision/image_read.h): the PNG, JPEG, BMP
// and TIFF header parsers that size an image before any pixel is decoded. The whole input is the
// file. A finding is a crash, an exception other than hecal::InputError, or an accepted header
// with a negative size. Headers accepted as small images (at most 10^6 pixels) are also decoded
// with cv::imdecode, as ReadGrayImage does, so a file the size check lets through cannot crash
// the codec either.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/vision/image_read.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  hecal::vision::ImageSize image;
  try {
    image = hecal::vision::ImageHeaderSize("fuzz", bytes);
  } catch (const hecal::InputError&) {
    return 0;  // refused with a reason: the expected outcome for most inputs
  }
  if (image.width < 0 || image.height < 0) {
    std::fprintf(stderr, "image property violated: negative size %dx%d\n", image.width,
                 image.height);
    std::abort();
  }
  if (image.width > 0 && image.height > 0 &&
      std::int64_t{image.width} * image.height <= 1'000'000) {
    const std::vector<uchar> buffer(data, data + size);
    (void)cv::imdecode(buffer, cv::IMREAD_GRAYSCALE);
  }
  return 0;
}
