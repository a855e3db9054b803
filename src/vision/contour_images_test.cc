// EncodePng and TrackImageSequence (contour_images.h) on files: a frame survives PNG encoding
// and ImageRead's decoding pixel for pixel, and a sequence whose images differ in size is
// refused naming the image.
#include "hecal/vision/contour_images.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/image_files.h"
#include "hecal/vision/image_read.h"
#include "testing/thrown.h"

namespace hecal::vision {
namespace {

class ContourImagesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("hecal_contour_images_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // A w × h ramp, value (3x + 7y) mod 256, written as dir_/name.
  std::string WriteRamp(const std::string& name, int w, int h) {
    contour::GrayImage image(w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) image.at(x, y) = static_cast<float>((3 * x + 7 * y) % 256);
    }
    const std::string path = (dir_ / name).string();
    io::WriteFileAtomically(path, EncodePng(image, path));
    return path;
  }

  std::filesystem::path dir_;
};

TEST_F(ContourImagesTest, PngRoundTripIsExact) {
  const std::string path = WriteRamp("ramp.png", 37, 23);
  const cv::Mat read = ReadGrayImage(path, io::kMinImageSide);
  ASSERT_EQ(read.cols, 37);
  ASSERT_EQ(read.rows, 23);
  for (int y = 0; y < 23; ++y) {
    for (int x = 0; x < 37; ++x) ASSERT_EQ(read.at<unsigned char>(y, x), (3 * x + 7 * y) % 256);
  }
}

TEST_F(ContourImagesTest, ImagesOfAnotherSizeAreRefused) {
  WriteRamp("frame_0000.png", 64, 48);
  const std::string second = WriteRamp("frame_0001.png", 48, 64);
  contour::SequenceTrackingOptions options;
  options.control.resize(2, 4);
  options.control << 20, 40, 40, 20, 10, 10, 30, 30;  // a square in the first image
  options.principal = {30, 20};
  options.camera = {500.0, 1000.0};
  contour::SequenceTracker tracker(options);
  int tracked = 0;
  const InputError error = testing::Thrown<InputError>([&] {
    TrackImageSequence(dir_.string(), &tracker, [&](const TrackedImage&) { ++tracked; });
  });
  EXPECT_EQ(tracked, 1);  // the first frame, before the second is read
  EXPECT_EQ(error.source(), second);
  EXPECT_NE(error.problem().find("the image is 48×64, the first was 64×48"), std::string::npos)
      << error.problem();
}

}  // namespace
}  // namespace hecal::vision
