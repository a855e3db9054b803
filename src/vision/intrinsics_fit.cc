// Do given intrinsics fit the images: see intrinsics_fit.h.
#include "hecal/vision/intrinsics_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/pose/pose_refinement.h"
#include "hecal/vision/opencv_pnp.h"

namespace hecal::vision {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Views with fewer points have no redundancy left for a homography worth comparing.
constexpr std::size_t kMinFreePoints = 6;
// A correction is named when it fits this many times better than the given intrinsics.
constexpr double kCorrectionGain = 4.0;
// The points are blamed, not K, when the free fit leaves at least half of E and this much.
constexpr double kPointsBlameRatio = 2.0;
constexpr double kPointsBlamePx = 1.0;
// The scale search: k over [1/20, 20], a log-spaced grid then golden-section refinement.
constexpr double kLargestScale = 20.0;
constexpr int kScaleGrid = 41;
constexpr int kGoldenSteps = 20;

double Median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// e: the reprojection RMS of the maximum-likelihood pose; infinity when there is no pose.
double PoseRms(const CalibrationView& view, const pose::CameraModel& camera) {
  try {
    const Pose T = SolvePnPOpenCvRefined(view.object_points, view.image_points, camera);
    return pose::RmsPx(
        pose::ReprojectionResiduals(T, view.object_points, view.image_points, camera));
  } catch (const DegenerateError&) {
    return kInfinity;
  } catch (const InputError&) {
    return kInfinity;  // e.g. a pixel that this camera's distortion cannot undistort
  }
}

// h: the RMS of the best homography to the undistorted pixels (in pixels of the given K);
// nullopt for views under kMinFreePoints points, infinity when a pixel cannot be undistorted.
std::optional<double> FreeRms(const CalibrationView& view, const pose::CameraModel& camera) {
  if (view.object_points.size() < kMinFreePoints) return std::nullopt;
  std::vector<cv::Point2d> plane, ideal;
  for (std::size_t k = 0; k < view.object_points.size(); ++k) {
    const std::optional<Eigen::Vector2d> n = pose::Undistort(camera, view.image_points[k]);
    if (!n) return kInfinity;
    plane.emplace_back(view.object_points[k].x(), view.object_points[k].y());
    ideal.emplace_back(camera.fx * n->x() + camera.cx, camera.fy * n->y() + camera.cy);
  }
  const cv::Mat H = cv::findHomography(plane, ideal, 0);
  if (H.empty()) return kInfinity;
  std::vector<cv::Point2d> mapped;
  cv::perspectiveTransform(plane, mapped, H);
  double sum = 0.0;
  for (std::size_t k = 0; k < ideal.size(); ++k) {
    const cv::Point2d d = mapped[k] - ideal[k];
    sum += d.dot(d);
  }
  return std::sqrt(sum / static_cast<double>(ideal.size()));
}

double MedianPoseRms(const std::vector<CalibrationView>& views, const pose::CameraModel& camera) {
  std::vector<double> rms;
  for (const CalibrationView& view : views) rms.push_back(PoseRms(view, camera));
  return Median(rms);
}

pose::CameraModel ScaledFocal(pose::CameraModel camera, double k) {
  camera.fx *= k;
  camera.fy *= k;
  return camera;
}

pose::CameraModel ScaledResolution(pose::CameraModel camera, double k) {
  camera = ScaledFocal(camera, k);
  camera.cx = (camera.cx + 0.5) * k - 0.5;
  camera.cy = (camera.cy + 0.5) * k - 0.5;
  return camera;
}

// The scale k in [1/20, 20] (log-spaced grid, then golden section on log k around the best grid
// point) that minimises E for camera(k).
template <typename Camera>
IntrinsicsCorrection BestScale(const std::vector<CalibrationView>& views,
                               IntrinsicsCorrection::Kind kind, Camera camera_at) {
  const double span = std::log(kLargestScale);
  const auto cost = [&](double log_k) { return MedianPoseRms(views, camera_at(std::exp(log_k))); };
  const double step = 2.0 * span / (kScaleGrid - 1);
  double best_log = 0.0;
  double best_cost = kInfinity;
  for (int i = 0; i < kScaleGrid; ++i) {
    const double log_k = -span + i * step;
    const double c = cost(log_k);
    if (c < best_cost) {
      best_cost = c;
      best_log = log_k;
    }
  }
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = best_log - step, b = best_log + step;
  double x1 = b - ratio * (b - a), x2 = a + ratio * (b - a);
  double c1 = cost(x1), c2 = cost(x2);
  for (int i = 0; i < kGoldenSteps; ++i) {
    if (c1 < c2) {
      b = x2;
      x2 = x1;
      c2 = c1;
      x1 = b - ratio * (b - a);
      c1 = cost(x1);
    } else {
      a = x1;
      x1 = x2;
      c1 = c2;
      x2 = a + ratio * (b - a);
      c2 = cost(x2);
    }
  }
  if (std::min(c1, c2) < best_cost) {
    best_log = c1 < c2 ? x1 : x2;
    best_cost = std::min(c1, c2);
  }
  const double k = std::exp(best_log);
  return {kind, k, camera_at(k), best_cost};
}

// The best of the simple corrections (intrinsics_fit.h), scored on `views`.
IntrinsicsCorrection BestCorrection(const std::vector<CalibrationView>& views,
                                    const pose::CameraModel& camera) {
  using Kind = IntrinsicsCorrection::Kind;
  std::vector<IntrinsicsCorrection> tried;
  pose::CameraModel swapped = camera;
  std::swap(swapped.cx, swapped.cy);
  tried.push_back({Kind::kSwapPrincipalPoint, 1.0, swapped, MedianPoseRms(views, swapped)});
  tried.push_back(
      BestScale(views, Kind::kScaleFocal, [&camera](double k) { return ScaledFocal(camera, k); }));
  tried.push_back(BestScale(views, Kind::kScaleResolution,
                            [&camera](double k) { return ScaledResolution(camera, k); }));
  pose::CameraModel undistorted = camera;
  undistorted.distortion = {0.0, 0.0, 0.0, 0.0, 0.0};
  tried.push_back({Kind::kNoDistortion, 1.0, undistorted, MedianPoseRms(views, undistorted)});
  return *std::min_element(tried.begin(), tried.end(),
                           [](const IntrinsicsCorrection& a, const IntrinsicsCorrection& b) {
                             return a.median_rms_px < b.median_rms_px;
                           });
}

void CheckViews(const std::vector<CalibrationView>& views) {
  if (views.empty()) throw InputError("views", 0, "no views", "give at least one view");
  for (std::size_t i = 0; i < views.size(); ++i) {
    const CalibrationView& view = views[i];
    if (view.object_points.size() != view.image_points.size() || view.object_points.size() < 4) {
      throw InputError("views", static_cast<int>(i + 1),
                       "a view needs as many pixels as object points, at least 4",
                       "pass the points of one detection per view");
    }
  }
}

}  // namespace

bool IntrinsicsFitOptions::IsValid(std::string* why) const {
  const std::pair<const char*, double> thresholds[] = {
      {"IntrinsicsFitOptions.refuse_rms_px", refuse_rms_px},
      {"IntrinsicsFitOptions.warn_ratio", warn_ratio},
      {"IntrinsicsFitOptions.min_warn_rms_px", min_warn_rms_px},
      {"IntrinsicsFitOptions.warn_rms_px_without_free", warn_rms_px_without_free},
      {"IntrinsicsFitOptions.free_floor_px", free_floor_px}};
  for (const auto& [field, value] : thresholds) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      return Invalid(why, field, "must be a finite number above 0",
                     "give a positive threshold (the defaults are in intrinsics_fit.h)");
    }
  }
  if (max_diagnosis_views < 1) {
    return Invalid(why, "IntrinsicsFitOptions.max_diagnosis_views",
                   "must be at least 1, got " + std::to_string(max_diagnosis_views),
                   "give the number of views the diagnosis refits (default 10)");
  }
  return true;
}

IntrinsicsFit CheckIntrinsicsFit(const std::vector<CalibrationView>& views,
                                 const pose::CameraModel& camera,
                                 const IntrinsicsFitOptions& options) {
  RequireValid(options);
  CheckViews(views);
  IntrinsicsFit fit;
  fit.median_rms_px = MedianPoseRms(views, camera);
  std::vector<double> free;
  for (const CalibrationView& view : views) {
    if (const std::optional<double> h = FreeRms(view, camera)) free.push_back(*h);
  }
  if (!free.empty()) fit.median_free_rms_px = Median(free);

  const double E = fit.median_rms_px;
  if (E >= options.refuse_rms_px) {
    fit.verdict = IntrinsicsVerdict::kDoesNotFit;
  } else if (fit.median_free_rms_px) {
    const double floor = std::max(*fit.median_free_rms_px, options.free_floor_px);
    if (E >= options.warn_ratio * floor && E >= options.min_warn_rms_px) {
      fit.verdict = IntrinsicsVerdict::kSuspect;
    }
  } else if (E >= options.warn_rms_px_without_free) {
    fit.verdict = IntrinsicsVerdict::kSuspect;
  }
  if (fit.verdict == IntrinsicsVerdict::kFits) return fit;

  fit.points_do_not_fit = fit.median_free_rms_px && *fit.median_free_rms_px >= kPointsBlamePx &&
                          E < kPointsBlameRatio * *fit.median_free_rms_px;
  const std::vector<CalibrationView> sample(
      views.begin(),
      views.begin() + std::min<long>(static_cast<long>(views.size()), options.max_diagnosis_views));
  IntrinsicsCorrection best = BestCorrection(sample, camera);
  if (best.median_rms_px * kCorrectionGain <= MedianPoseRms(sample, camera)) {
    fit.correction = std::move(best);
  }
  return fit;
}

}  // namespace hecal::vision
