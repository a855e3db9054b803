// Contour sequences as image files: see contour_images.h.
#include "hecal/vision/contour_images.h"

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "hecal/core/error.h"
#include "hecal/io/image_files.h"
#include "hecal/vision/image_read.h"

namespace hecal::vision {

namespace {

contour::GrayImage ReadGray(const std::filesystem::path& path) {
  const cv::Mat pixels = ReadGrayImage(path.string(), io::kMinImageSide);
  contour::GrayImage image(pixels.cols, pixels.rows);
  for (int y = 0; y < pixels.rows; ++y) {
    const unsigned char* row = pixels.ptr<unsigned char>(y);
    for (int x = 0; x < pixels.cols; ++x) image.at(x, y) = static_cast<float>(row[x]);
  }
  return image;
}

}  // namespace

std::vector<TrackedImage> TrackImageSequence(
    const std::string& dir, contour::SequenceTracker* tracker,
    const std::function<void(const TrackedImage&)>& on_frame) {
  const std::vector<std::filesystem::path> files = io::ListImageFiles(dir, "the image sequence");
  std::vector<TrackedImage> frames;
  int width = -1, height = -1;
  for (const std::filesystem::path& file : files) {
    const contour::GrayImage image = ReadGray(file);
    if (width < 0) {
      width = image.width();
      height = image.height();
    } else if (image.width() != width || image.height() != height) {
      throw InputError(file.string(), 0,
                       "the image is " + std::to_string(image.width()) + "×" +
                           std::to_string(image.height()) + ", the first was " +
                           std::to_string(width) + "×" + std::to_string(height),
                       "give a sequence of images of one size");
    }
    TrackedImage frame;
    frame.image = file.filename().string();
    frame.frame = tracker->Track(image);
    if (on_frame) on_frame(frame);
    frames.push_back(std::move(frame));
  }
  return frames;
}

std::string EncodePng(const contour::GrayImage& image, const std::string& path) {
  cv::Mat pixels(image.height(), image.width(), CV_8UC1);
  for (int y = 0; y < image.height(); ++y) {
    unsigned char* row = pixels.ptr<unsigned char>(y);
    for (int x = 0; x < image.width(); ++x) row[x] = static_cast<unsigned char>(image.at(x, y));
  }
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", pixels, png)) {
    throw InputError(path, 0, "cannot encode the image", "check the OpenCV build (PNG support)");
  }
  return std::string(reinterpret_cast<const char*>(png.data()), png.size());
}

}  // namespace hecal::vision
