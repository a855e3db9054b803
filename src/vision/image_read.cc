// Reading one image file, bounded: see image_read.h.
#include "hecal/vision/image_read.h"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/image_files.h"

namespace hecal::vision {
namespace {

enum class Format { kPng, kJpeg, kBmp, kTiff };

std::uint32_t BigEndian(const std::string& b, std::size_t at, int bytes) {
  std::uint32_t value = 0;
  for (int i = 0; i < bytes; ++i) value = (value << 8) | static_cast<unsigned char>(b[at + i]);
  return value;
}

std::uint32_t LittleEndian(const std::string& b, std::size_t at, int bytes) {
  std::uint32_t value = 0;
  for (int i = bytes - 1; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(b[at + i]);
  return value;
}

[[noreturn]] void CannotDecode(const std::string& path, const std::string& why) {
  throw InputError(path, 0, "cannot decode the image: " + why,
                   "replace it with a readable png/jpg/bmp/tif (re-export or copy it again), or "
                   "remove it");
}

Format FormatOf(const std::string& path, const std::string& b) {
  if (b.size() >= 8 && b.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return Format::kPng;
  if (b.size() >= 3 && b.compare(0, 3, "\xff\xd8\xff") == 0) return Format::kJpeg;
  if (b.size() >= 2 && b.compare(0, 2, "BM") == 0) return Format::kBmp;
  if (b.size() >= 4 && (b.compare(0, 4, std::string("II*\0", 4)) == 0 ||
                        b.compare(0, 4, std::string("MM\0*", 4)) == 0)) {
    return Format::kTiff;
  }
  CannotDecode(path, "it is not a PNG, JPEG, BMP or TIFF file (unknown header)");
}

ImageSize JpegSize(const std::string& path, const std::string& b) {
  std::size_t at = 2;
  while (at + 4 <= b.size()) {
    if (static_cast<unsigned char>(b[at]) != 0xff) break;
    const unsigned char marker = static_cast<unsigned char>(b[at + 1]);
    if (marker == 0xff) {  // fill byte
      ++at;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) {  // no length
      at += 2;
      continue;
    }
    const std::uint32_t length = BigEndian(b, at + 2, 2);
    const bool frame =
        marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
    if (frame) {
      if (at + 9 > b.size()) break;
      return {static_cast<int>(BigEndian(b, at + 7, 2)), static_cast<int>(BigEndian(b, at + 5, 2))};
    }
    if (length < 2) break;
    at += 2 + length;
  }
  CannotDecode(path, "the JPEG header has no frame size (the file is cut short or corrupt)");
}

ImageSize TiffSize(const std::string& path, const std::string& b) {
  const bool little = b[0] == 'I';
  const auto read = [&](std::size_t at, int bytes) {
    return little ? LittleEndian(b, at, bytes) : BigEndian(b, at, bytes);
  };
  if (b.size() < 8) CannotDecode(path, "the TIFF header is cut short");
  const std::size_t ifd = read(4, 4);
  if (ifd + 2 > b.size()) CannotDecode(path, "the TIFF header is cut short");
  const std::uint32_t entries = read(ifd, 2);
  long width = -1, height = -1;
  for (std::uint32_t k = 0; k < entries; ++k) {
    const std::size_t entry = ifd + 2 + 12 * static_cast<std::size_t>(k);
    if (entry + 12 > b.size()) break;
    const std::uint32_t tag = read(entry, 2), type = read(entry + 2, 2);
    const std::uint32_t value = type == 3 ? read(entry + 8, 2) : read(entry + 8, 4);  // SHORT
    if (tag == 256) width = value;
    if (tag == 257) height = value;
  }
  if (width < 0 || height < 0) CannotDecode(path, "the TIFF header has no image size");
  return {static_cast<int>(std::min<long>(width, INT32_MAX)),
          static_cast<int>(std::min<long>(height, INT32_MAX))};
}

// The codecs print their complaints on file descriptor 2; this captures them while one file is
// decoded (one at a time: the descriptor is the process's).
class CapturedStderr {
 public:
  CapturedStderr() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    saved_ = dup(2);
    if (file_ == nullptr || saved_ < 0 || dup2(fileno(file_), 2) < 0) {
      Restore();
      if (file_ != nullptr) std::fclose(file_);
      file_ = nullptr;
    }
  }
  ~CapturedStderr() {
    Restore();
    if (file_ != nullptr) std::fclose(file_);
  }
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;

  // What was written, the lines joined by "; ".
  std::string Text() {
    Restore();
    if (file_ == nullptr) return "";
    std::string text;
    std::rewind(file_);
    char buffer[512];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, file_)) > 0 && text.size() < 4096) {
      text.append(buffer, n);
    }
    std::string joined;
    std::size_t start = 0;
    while (start < text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      if (end > start) joined += (joined.empty() ? "" : "; ") + text.substr(start, end - start);
      start = end + 1;
    }
    return joined;
  }

 private:
  void Restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    dup2(saved_, 2);
    close(saved_);
    saved_ = -1;
  }
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

std::mutex& DecodeMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

ImageSize ImageHeaderSize(const std::string& path, const std::string& b) {
  switch (FormatOf(path, b)) {
    case Format::kPng:
      if (b.size() < 24 || b.compare(12, 4, "IHDR") != 0) {
        CannotDecode(path, "the PNG header is cut short");
      }
      return {static_cast<int>(std::min<std::uint32_t>(BigEndian(b, 16, 4), INT32_MAX)),
              static_cast<int>(std::min<std::uint32_t>(BigEndian(b, 20, 4), INT32_MAX))};
    case Format::kJpeg:
      return JpegSize(path, b);
    case Format::kBmp: {
      if (b.size() < 26) CannotDecode(path, "the BMP header is cut short");
      const auto width = static_cast<std::int32_t>(LittleEndian(b, 18, 4));
      const auto height = static_cast<std::int32_t>(LittleEndian(b, 22, 4));
      return {width == INT32_MIN ? INT32_MAX : std::abs(width),
              height == INT32_MIN ? INT32_MAX : std::abs(height)};
    }
    case Format::kTiff:
      return TiffSize(path, b);
  }
  CannotDecode(path, "unknown format");
}

cv::Mat ReadGrayImage(const std::string& path, int min_side) {
  const std::string bytes = io::ReadFile(path);
  const ImageSize size = ImageHeaderSize(path, bytes);
  const std::int64_t pixels = std::int64_t{size.width} * size.height;
  if (pixels > io::kMaxImagePixels) {
    throw InputError(path, 0,
                     "the image is " + std::to_string(size.width) + "x" +
                         std::to_string(size.height) + ", more than " +
                         std::to_string(io::kMaxImagePixels / 1000000) +
                         " megapixels, the most hecal reads",
                     "give images of at most 100 megapixels (scale them down)");
  }
  if (size.width < min_side || size.height < min_side) {
    throw InputError(path, 0,
                     "the image is " + std::to_string(size.width) + "x" +
                         std::to_string(size.height) + ", smaller than " +
                         std::to_string(min_side) + "x" + std::to_string(min_side) +
                         " pixels, too small to find a target in",
                     "give the camera's full-size images");
  }
  const bool jpeg = FormatOf(path, bytes) == Format::kJpeg;
  // libjpeg fills a JPEG cut short with grey, silently when reading from memory: look for the
  // end-of-image marker (ITU-T T.81 §B.2.1) after the start of the scan.
  if (jpeg) {
    const std::size_t scan = bytes.find("\xff\xda");
    const std::size_t end = bytes.rfind("\xff\xd9");
    if (scan == std::string::npos || end == std::string::npos || end < scan) {
      CannotDecode(path, "the JPEG file is cut short (no end-of-image marker after the scan)");
    }
  }
  const std::vector<unsigned char> buffer(bytes.begin(), bytes.end());
  cv::Mat gray;
  std::string complaint;
  {
    const std::lock_guard<std::mutex> lock(DecodeMutex());
    CapturedStderr captured;
    try {
      gray = cv::imdecode(buffer, cv::IMREAD_GRAYSCALE);
    } catch (const cv::Exception& error) {
      complaint = error.err;
    }
    const std::string codec = captured.Text();
    if (!codec.empty()) complaint = complaint.empty() ? codec : codec + "; " + complaint;
  }
  // libjpeg recovers from a corrupt stream with grey blocks and a warning: refuse it.
  if (gray.empty() || (jpeg && !complaint.empty())) {
    CannotDecode(path, complaint.empty() ? "the decoder failed (corrupt file)" : complaint);
  }
  if (gray.cols != size.width || gray.rows != size.height) {
    CannotDecode(path, "the decoded size differs from the header's");
  }
  return gray;
}

}  // namespace hecal::vision
