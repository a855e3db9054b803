// Synthetic images of a planar contour target for the tracker's tests and `hecal contour render`
// (the forward model of docs/contour.md#the-experiments made into pixels): a filled closed polygon,
// anti-aliased by area coverage, plus additive Gaussian pixel noise.
//
// Coverage. Pixel (x, y) covers the unit square centred on (x, y) (OpenCV's convention, as in
// gray_image.h). Its value is background + (foreground − background) · c, c ∈ [0, 1] the
// fraction of the square inside the polygon (even–odd rule). c is computed by supersampling in y
// — `supersampling` scanlines per pixel row, at the centres of equal sub-rows — and exactly in x:
// each scanline is cut by the polygon into inside intervals whose overlap with every pixel's
// [x − ½, x + ½] is added as a length. So edges are located exactly along x and to within half a
// sub-row along y. Σ c is the midpoint rule for the polygon's area, exact for sub-rows without a
// vertex; the error comes from vertices and from the top and bottom of curved outlines, where the
// width varies as a square root: O(n^{-3/2}) (a 17 px radius disc: 0.03 px² at n = 16).
//
// Optics: the coverage is then blurred by a Gaussian point-spread function of blur_sigma px
// (separable, taps within ±3σ, border pixels repeated; 0 turns it off). A real lens and sensor
// never image a perfectly sharp step; without the blur an area-sampled step is aliased, and
// bilinear interpolation of it places an oblique edge with a position error that depends on its
// sub-pixel phase ("pixel locking": measured with edge_search.h, 0.04 px RMS and 0.1 px worst
// without blur, 0.016 px RMS with the default 0.7 px).
//
// Noise: i.i.d. N(0, σ²) added to every pixel from std::mt19937_64 seeded with
// SplitMix64(seed), in row-major order (reproducible for a seed on one standard library).
// Optional quantisation rounds to integer grey levels and clamps to [0, 255], as an 8-bit image.
//
// The planar target (RenderPlanarTarget): the target is a closed B-spline in its plane (unit of
// Z0), sampled densely (samples_per_span points per span; the chord error of the polygon is
// then far below 0.01 px for targets of a few hundred pixels), projected by the true pinhole
// ProjectPerspective (perspective_view.h) after the motion (R, T), and shifted by the principal
// point into pixel coordinates. The image of the B-spline is not itself an affine image of the
// template B-spline: weak perspective's model error is in the pixels, as in a real camera.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/bspline.h"
#include "hecal/contour/gray_image.h"

namespace hecal::contour {

struct RenderOptions {
  double foreground = 180.0;  // grey level inside the polygon
  double background = 60.0;   // grey level outside
  int supersampling = 16;     // scanlines per pixel row (≥ 1)
  double blur_sigma = 0.7;    // Gaussian point-spread function (px, ≥ 0; 0 = none)
  double noise_sigma = 0.0;   // grey levels (≥ 0)
  std::uint64_t seed = 0;
  bool quantize = false;  // round to integers in [0, 255] after the noise

  // core/options_check.h: false naming RenderOptions.foreground or .background (not finite),
  // .supersampling (below 1), .blur_sigma or .noise_sigma (negative or not finite).
  bool IsValid(std::string* why) const;
};

// The polygon (2 × M vertices, pixel coordinates, closed implicitly) filled with coverage
// anti-aliasing, blurred, then noise and quantisation. Throws hecal::InputError when
// !options.IsValid, std::invalid_argument for a negative size, fewer than 3 vertices or
// non-finite vertices.
GrayImage RenderPolygon(const Eigen::Matrix2Xd& polygon, int width, int height,
                        const RenderOptions& options);

// The coverage c of every pixel (0 … 1), no levels, noise or quantisation.
GrayImage PolygonCoverage(const Eigen::Matrix2Xd& polygon, int width, int height,
                          int supersampling);

// Blurs with a Gaussian of `sigma` px (see above); sigma = 0 leaves the image unchanged.
void GaussianBlur(GrayImage* image, double sigma);
// Adds N(0, sigma²) to every pixel (see above). sigma = 0 leaves the image unchanged.
void AddGaussianNoise(GrayImage* image, double sigma, std::uint64_t seed);
// Rounds every pixel to the nearest integer and clamps it to [0, 255].
void QuantizeGrey(GrayImage* image);

// The outline of the planar target `target` (control points in the target plane, Z0's unit)
// after the motion: samples_per_span points per span, in pixels (principal point added). Throws
// hecal::DegenerateError when a point is behind the camera.
Eigen::Matrix2Xd PerspectiveOutline(const ClosedBSpline& target, const Eigen::Matrix3d& rotation,
                                    const Eigen::Vector3d& translation, const ContourCamera& camera,
                                    const Eigen::Vector2d& principal_point,
                                    int samples_per_span = 64);

// RenderPolygon of PerspectiveOutline.
GrayImage RenderPlanarTarget(const ClosedBSpline& target, const Eigen::Matrix3d& rotation,
                             const Eigen::Vector3d& translation, const ContourCamera& camera,
                             const Eigen::Vector2d& principal_point, int width, int height,
                             const RenderOptions& options, int samples_per_span = 64);

}  // namespace hecal::contour
