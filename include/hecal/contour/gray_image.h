// A minimal grayscale image for the contour tracker (Blake and Isard, "Active Contours", 1998,
// ch. 5: the tracker only reads intensity profiles along curve normals) and the synthetic
// renderer: width × height float pixels, row-major (pixel (x, y) at index y · width + x).
//
// Coordinates follow OpenCV: the centre of pixel (x, y) is at the integer point (x, y), so pixel
// (x, y) covers [x − ½, x + ½] × [y − ½, y + ½] and the image covers [−½, w − ½] × [−½, h − ½].
// Sample(x, y) interpolates bilinearly between the four surrounding pixel centres, which is
// defined on [0, w − 1] × [0, h − 1] (Contains); outside that box the coordinates are clamped
// to it (the border pixels are repeated).
#pragma once

#include <cstddef>
#include <vector>

namespace hecal::contour {

class GrayImage {
 public:
  GrayImage() = default;
  // Throws std::invalid_argument for a negative size.
  GrayImage(int width, int height, float value = 0.0f);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return pixels_.empty(); }

  // Pixel (x, y): column x, row y (no bounds check beyond the vector's).
  float& at(int x, int y) { return pixels_[Index(x, y)]; }
  float at(int x, int y) const { return pixels_[Index(x, y)]; }
  std::vector<float>& pixels() { return pixels_; }
  const std::vector<float>& pixels() const { return pixels_; }

  // True when (x, y) lies in [0, w − 1] × [0, h − 1], where Sample needs no clamping.
  bool Contains(double x, double y) const;
  // Bilinear interpolation at (x, y) (see above). Requires a non-empty image.
  double Sample(double x, double y) const;

 private:
  std::size_t Index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
  }

  int width_ = 0;
  int height_ = 0;
  std::vector<float> pixels_;
};

}  // namespace hecal::contour
