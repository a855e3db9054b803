// One-dimensional edge search along a curve normal — the measurement process of the active
// contour (Blake and Isard, "Active Contours", 1998, ch. 5 "Image processing techniques for
// feature location", §5.1–5.3; the contour paper §II: the contour is attracted to the image edges).
//
// From a curve point r and its unit normal n, the intensity profile p(t) = I(r + t n) is sampled
// by bilinear interpolation (gray_image.h) at t_k = k · step, |t_k| ≤ range. Its derivative g is
// taken with a derivative-of-Gaussian filter of scale σ_d = derivative_sigma (taps at the profile
// samples within ±3σ_d, normalised so that a unit ramp has g = 1; Canny's optimal step detector,
// Blake and Isard §5.2): the smoothing keeps pixel noise from creating spurious peaks, and, the
// filter being symmetric, the peak of g over a blurred step stays at the step. (A plain central
// difference over ±1 px has a flat-topped response to a sharp edge, which biases the parabola
// below by up to a quarter pixel.) The edge is the strongest g — of either sign, or only of the
// expected polarity (+1: brighter along +n, −1: darker) — located to sub-sample precision by the
// vertex of the parabola through the peak and its two neighbours,
//   t* = t_k + step · ½ (g_{k−1} − g_{k+1}) / (g_{k−1} − 2 g_k + g_{k+1}).
// No edge (std::nullopt) when the peak's |g| is below min_gradient (grey levels per pixel), when
// the peak is at either end of the search interval (the edge may be beyond the range), or when
// the profile leaves the image.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "hecal/contour/gray_image.h"

namespace hecal::contour {

struct EdgeSearchOptions {
  double range = 10.0;            // px either side of the curve point
  double step = 0.5;              // px between profile samples
  double derivative_sigma = 1.0;  // σ_d of the derivative-of-Gaussian (px)
  double min_gradient = 10.0;     // grey levels / px
  int polarity = 0;               // +1, −1, or 0 for either

  // core/options_check.h: false naming EdgeSearchOptions.range (not positive and finite),
  // .step (not in (0, range]), .derivative_sigma (not positive and finite), .min_gradient
  // (negative or not finite) or .polarity (not −1, 0 or 1).
  bool IsValid(std::string* why) const;
};

struct EdgeHit {
  double offset = 0.0;    // t*: the edge is at r + t* n (px)
  double gradient = 0.0;  // g at the peak sample (signed, grey levels / px)
};

// Throws hecal::InputError (source "EdgeSearchOptions") for options out of range (range, step,
// σ_d ≤ 0, step > range, polarity not in {−1, 0, 1}), std::invalid_argument for a normal that is
// not a finite non-zero vector (it is normalised).
std::optional<EdgeHit> SearchEdge(const GrayImage& image, const Eigen::Vector2d& point,
                                  const Eigen::Vector2d& normal, const EdgeSearchOptions& options);

}  // namespace hecal::contour
