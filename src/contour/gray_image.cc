// A minimal grayscale image: see gray_image.h.
#include "hecal/contour/gray_image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hecal::contour {

GrayImage::GrayImage(int width, int height, float value) : width_(width), height_(height) {
  if (width < 0 || height < 0) {
    throw std::invalid_argument("GrayImage: negative size");
  }
  pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), value);
}

bool GrayImage::Contains(double x, double y) const {
  return width_ > 0 && height_ > 0 && x >= 0.0 && y >= 0.0 && x <= width_ - 1.0 &&
         y <= height_ - 1.0;
}

double GrayImage::Sample(double x, double y) const {
  if (empty()) throw std::invalid_argument("GrayImage::Sample: empty image");
  // NaN compares false everywhere; std::clamp would pass it through, so map it to 0 first.
  const double cx = std::clamp(std::isnan(x) ? 0.0 : x, 0.0, width_ - 1.0);
  const double cy = std::clamp(std::isnan(y) ? 0.0 : y, 0.0, height_ - 1.0);
  const int x0 = std::min(static_cast<int>(std::floor(cx)), std::max(width_ - 2, 0));
  const int y0 = std::min(static_cast<int>(std::floor(cy)), std::max(height_ - 2, 0));
  const int x1 = std::min(x0 + 1, width_ - 1);
  const int y1 = std::min(y0 + 1, height_ - 1);
  const double fx = cx - x0;
  const double fy = cy - y0;
  const double top = (1.0 - fx) * at(x0, y0) + fx * at(x1, y0);
  const double bottom = (1.0 - fx) * at(x0, y1) + fx * at(x1, y1);
  return (1.0 - fy) * top + fy * bottom;
}

}  // namespace hecal::contour
