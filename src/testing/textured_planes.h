// Test support (not installed, no OpenCV): images of a scene made of textured planar rectangles,
// for the target-free method on rendered images (docs/global.md, "Measured").
//
// Scene: TexturedPlane rectangles, each in its own frame T_world_plane (the plane z = 0, the
// rectangle |x| ≤ width/2, |y| ≤ height/2, metres), painted with a Texture: reflectance 0 (black)
// … 1 (white) at a point (x, y) of the plane's frame. BlobTexture is a texture rich in SIFT
// features: value noise (a hashed random level at every lattice point, interpolated with a
// smoothstep) summed over `octaves` lattices of pitch finest · 2^k, weight 2^k, and pushed through
// a steep logistic so that the blobs have sharp edges at every scale; deterministic in `seed`.
//
// Camera: the pinhole + plumb_bob model of pose/camera_model.h at T_world_camera
// (x_world = T_world_camera · x_camera; z forward, x right, y down). Pixels follow OpenCV: pixel
// (i, j) covers u ∈ [i − ½, i + ½], v ∈ [j − ½, j + ½]. As in vision/render.h, every pixel corner
// is undistorted (pose::Undistort) and the normalised coordinates are interpolated bilinearly
// inside the pixel. Every pixel averages supersampling² samples on a stratified grid jittered by a
// hash of the pixel position (area anti-aliasing). A sample's ray (x, y, 1) is cut with every
// plane; the nearest cut in front of the camera (depth > 0) that falls inside its rectangle wins
// (occlusion), and the sample reads that plane's texture there; a ray that meets no rectangle
// reads `background`. The image of a plane point P is therefore at
// pose::Project(camera, T_world_camera⁻¹ · P) (textured_planes_test). Then, in this order:
// Gaussian blur of blur_sigma px (separable, kernel to 4σ, borders replicated; none when 0),
// additive Gaussian noise of noise_sigma grey levels (std::mt19937_64 seeded with `seed`),
// rounding and saturation to 8 bits. Reflectance r is the grey level black + r · (white − black).
//
// Errors: none are raised; pixel corners that cannot be undistorted read the background.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "hecal/core/pixel_jitter.h"
#include "hecal/core/random_draws.h"
#include "hecal/core/split_mix.h"
#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"

namespace hecal::testing {

// Reflectance 0 … 1 at (x, y) in a plane's frame, metres.
using Texture = std::function<double(double x, double y)>;

struct TexturedPlane {
  Pose T_world_plane = Pose::Identity();  // the plane z = 0 of this frame
  double width = 1.0;                     // metres along the plane's x
  double height = 1.0;                    // metres along the plane's y
  Texture texture;
};

// Multi-scale blobs (see above): lattice pitches finest, 2·finest, … (metres).
inline Texture BlobTexture(std::uint64_t seed, double finest = 0.004, int octaves = 4) {
  return [seed, finest, octaves](double x, double y) {
    double sum = 0.0, weights = 0.0;
    for (int k = 0; k < octaves; ++k) {
      const double pitch = finest * std::ldexp(1.0, k);
      const double u = x / pitch, v = y / pitch;
      const double fu = std::floor(u), fv = std::floor(v);
      const auto level = [&](double i, double j) {
        const std::uint64_t key = SplitMix64(
            SplitMix64(seed * 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(k)) ^
            (static_cast<std::uint64_t>(static_cast<std::int64_t>(i)) * 0x100000001b3ULL +
             static_cast<std::uint64_t>(static_cast<std::int64_t>(j))));
        return UnitInterval(SplitMix64(key));
      };
      const auto smooth = [](double s) { return s * s * (3.0 - 2.0 * s); };
      const double a = smooth(u - fu), b = smooth(v - fv);
      const double value = (1 - b) * ((1 - a) * level(fu, fv) + a * level(fu + 1, fv)) +
                           b * ((1 - a) * level(fu, fv + 1) + a * level(fu + 1, fv + 1));
      const double weight = std::ldexp(1.0, k);
      sum += weight * value;
      weights += weight;
    }
    return 1.0 / (1.0 + std::exp(-12.0 * (sum / weights - 0.5)));
  };
}

struct PlaneRenderOptions {
  int supersampling = 3;      // samples per pixel along each axis, ≥ 1
  double blur_sigma = 0.0;    // pixels
  double noise_sigma = 0.0;   // grey levels
  double background = 128.0;  // grey level where no plane is hit
  double black = 20.0;        // grey level of reflectance 0
  double white = 235.0;       // grey level of reflectance 1
  std::uint64_t seed = 1;     // noise
};

// An 8-bit grey image, row-major.
struct GreyImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // pixel (i, j) at j · width + i

  std::uint8_t At(int i, int j) const {
    return pixels[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(i)];
  }
};

// Separable Gaussian blur of a row-major float image, borders replicated.
inline void GaussianBlurInPlace(std::vector<double>& image, int width, int height, double sigma) {
  const int radius = std::max(1, static_cast<int>(std::ceil(4.0 * sigma)));
  std::vector<double> kernel(static_cast<std::size_t>(2 * radius + 1));
  double total = 0.0;
  for (int k = -radius; k <= radius; ++k) {
    total += kernel[static_cast<std::size_t>(k + radius)] =
        std::exp(-0.5 * k * k / (sigma * sigma));
  }
  for (double& w : kernel) w /= total;
  std::vector<double> pass(image.size());
  const auto at = [width](int i, int j) {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(i);
  };
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      double sum = 0.0;
      for (int k = -radius; k <= radius; ++k) {
        sum += kernel[static_cast<std::size_t>(k + radius)] *
               image[at(std::clamp(i + k, 0, width - 1), j)];
      }
      pass[at(i, j)] = sum;
    }
  }
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      double sum = 0.0;
      for (int k = -radius; k <= radius; ++k) {
        sum += kernel[static_cast<std::size_t>(k + radius)] *
               pass[at(i, std::clamp(j + k, 0, height - 1))];
      }
      image[at(i, j)] = sum;
    }
  }
}

// The image of `planes` seen by `camera` at T_world_camera (see above); camera.width × height.
inline GreyImage RenderPlanes(const std::vector<TexturedPlane>& planes,
                              const pose::CameraModel& camera, const Pose& T_world_camera,
                              const PlaneRenderOptions& options = {}) {
  const int width = camera.width, height = camera.height;
  // Each plane in the camera frame: its normal n and origin o; a ray d meets it at depth
  // λ = n·o / n·d, at the plane point R_cpᵀ (λ d − o).
  struct InCamera {
    Eigen::Matrix3d R;
    Eigen::Vector3d o;
  };
  std::vector<InCamera> in_camera;
  for (const TexturedPlane& plane : planes) {
    const Pose T_camera_plane = T_world_camera.inverse() * plane.T_world_plane;
    in_camera.push_back({T_camera_plane.linear(), T_camera_plane.translation()});
  }
  const auto grey_of_ray = [&](const Eigen::Vector3d& d) {
    double nearest = std::numeric_limits<double>::infinity();
    double reflectance = -1.0;
    for (std::size_t k = 0; k < planes.size(); ++k) {
      const Eigen::Vector3d n = in_camera[k].R.col(2);
      const double along = n.dot(d);
      if (along == 0.0) continue;
      const double depth = n.dot(in_camera[k].o) / along;
      if (!(depth > 0.0) || depth >= nearest) continue;
      const Eigen::Vector3d p = in_camera[k].R.transpose() * (depth * d - in_camera[k].o);
      if (std::abs(p.x()) > 0.5 * planes[k].width || std::abs(p.y()) > 0.5 * planes[k].height) {
        continue;
      }
      nearest = depth;
      reflectance = planes[k].texture(p.x(), p.y());
    }
    return reflectance < 0.0 ? options.background
                             : options.black + reflectance * (options.white - options.black);
  };

  const int corner_cols = width + 1;
  std::vector<std::optional<Eigen::Vector2d>> corners;
  corners.reserve(static_cast<std::size_t>(corner_cols) * static_cast<std::size_t>(height + 1));
  for (int j = 0; j <= height; ++j) {
    for (int i = 0; i <= width; ++i) {
      corners.push_back(pose::Undistort(camera, Eigen::Vector2d(i - 0.5, j - 0.5)));
    }
  }
  const int s = std::max(1, options.supersampling);
  std::vector<double> image(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const std::size_t k00 = static_cast<std::size_t>(j) * static_cast<std::size_t>(corner_cols) +
                              static_cast<std::size_t>(i);
      const std::size_t k01 = k00 + static_cast<std::size_t>(corner_cols);
      double& grey = image[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
                           static_cast<std::size_t>(i)];
      if (!corners[k00] || !corners[k00 + 1] || !corners[k01] || !corners[k01 + 1]) {
        grey = options.background;
        continue;
      }
      const Eigen::Vector2d &p00 = *corners[k00], &p10 = *corners[k00 + 1];
      const Eigen::Vector2d &p01 = *corners[k01], &p11 = *corners[k01 + 1];
      const std::uint64_t pixel_key = PixelKey(i, j);
      double sum = 0.0;
      for (int b = 0; b < s; ++b) {
        for (int a = 0; a < s; ++a) {
          const auto [fx, fy] = JitteredSample(pixel_key, a, b, s);
          const Eigen::Vector2d x =
              (1.0 - fy) * ((1.0 - fx) * p00 + fx * p10) + fy * ((1.0 - fx) * p01 + fx * p11);
          sum += grey_of_ray(Eigen::Vector3d(x.x(), x.y(), 1.0));
        }
      }
      grey = sum / (s * s);
    }
  }
  if (options.blur_sigma > 0.0) GaussianBlurInPlace(image, width, height, options.blur_sigma);
  if (options.noise_sigma > 0.0) {
    std::mt19937_64 generator(options.seed);
    hecal::NormalDistribution noise(0.0, options.noise_sigma);
    for (double& grey : image) grey += noise(generator);
  }
  GreyImage out{width, height, {}};
  out.pixels.reserve(image.size());
  for (const double grey : image) {
    out.pixels.push_back(static_cast<std::uint8_t>(std::clamp(std::lround(grey), 0L, 255L)));
  }
  return out;
}

}  // namespace hecal::testing
