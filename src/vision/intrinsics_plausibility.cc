// Plausibility of estimated intrinsics: see intrinsics_plausibility.h.
#include "hecal/vision/intrinsics_plausibility.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "hecal/core/options_check.h"
#include "hecal/io/delimited_text.h"

namespace hecal::vision {
namespace {

using io::FormatFixed;

constexpr int kFoldSteps = 1000;

// The normalised radius of the image corner farthest from the principal point.
double CornerRadius(const pose::CameraModel& camera) {
  const double x = std::max(camera.cx, camera.width - 1.0 - camera.cx) / camera.fx;
  const double y = std::max(camera.cy, camera.height - 1.0 - camera.cy) / camera.fy;
  return std::hypot(x, y);
}

}  // namespace

bool IntrinsicsPlausibilityOptions::IsValid(std::string* why) const {
  const std::pair<const char*, double> positive[] = {
      {"IntrinsicsPlausibilityOptions.max_rms_px", max_rms_px},
      {"IntrinsicsPlausibilityOptions.max_principal_offset", max_principal_offset}};
  for (const auto& [field, value] : positive) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      return Invalid(why, field, "must be a finite number above 0",
                     "give a positive threshold (the defaults are in intrinsics_plausibility.h)");
    }
  }
  if (!(max_focal_ratio > 1.0) || !std::isfinite(max_focal_ratio)) {
    return Invalid(why, "IntrinsicsPlausibilityOptions.max_focal_ratio",
                   "must be a finite number above 1",
                   "give a ratio above 1 (the default is in intrinsics_plausibility.h)");
  }
  return true;
}

double RadialFoldRadius(const pose::CameraModel& camera, double r_max) {
  const auto& d = camera.distortion;  // k1, k2, p1, p2, k3
  for (int step = 0; step <= kFoldSteps; ++step) {
    const double r = r_max * step / kFoldSteps;
    const double r2 = r * r;
    const double slope = 1.0 + r2 * (3.0 * d[0] + r2 * (5.0 * d[1] + r2 * 7.0 * d[4]));
    if (!(slope > 0.0)) return r;
  }
  return -1.0;
}

IntrinsicsPlausibility CheckIntrinsicsPlausible(const IntrinsicsResult& estimate,
                                                const IntrinsicsPlausibilityOptions& options) {
  RequireValid(options);
  IntrinsicsPlausibility result;
  const pose::CameraModel& c = estimate.camera;
  if (!(estimate.rms_px < options.max_rms_px)) {
    result.problems.push_back("reprojection RMS " + FormatFixed(estimate.rms_px, 2) +
                              " px (a correctly described target fits to about 0.1 px; " +
                              FormatFixed(options.max_rms_px, 1) + " px is the limit)");
  }
  const double ratio = std::max(c.fx, c.fy) / std::min(c.fx, c.fy);
  if (!(ratio <= options.max_focal_ratio)) {
    result.problems.push_back("fx " + FormatFixed(c.fx, 0) + " and fy " + FormatFixed(c.fy, 0) +
                              " px differ by a factor " + FormatFixed(ratio, 2) +
                              " (a real camera's differ by a few per cent)");
  }
  const double fold = RadialFoldRadius(c, CornerRadius(c));
  if (fold >= 0.0) {
    const auto& d = c.distortion;
    result.problems.push_back("the distortion (k1 " + io::FormatDouble(d[0]) + ", k2 " +
                              io::FormatDouble(d[1]) + ", k3 " + io::FormatDouble(d[4]) +
                              ") folds the image at " + FormatFixed(fold * c.fx, 0) +
                              " px from the principal point, inside the image (no lens does)");
  }
  const double off_x = std::abs(c.cx - 0.5 * (c.width - 1)) / c.width;
  const double off_y = std::abs(c.cy - 0.5 * (c.height - 1)) / c.height;
  if (!(std::max(off_x, off_y) <= options.max_principal_offset)) {
    result.problems.push_back("the principal point (" + FormatFixed(c.cx, 0) + ", " +
                              FormatFixed(c.cy, 0) + ") is " +
                              FormatFixed(100.0 * std::max(off_x, off_y), 0) +
                              " % of the image from its centre (a lens is centred to a few %)");
  }
  return result;
}

}  // namespace hecal::vision
