#include "hecal/vision/intrinsics_calibration.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <sstream>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/so3.h"

namespace hecal::vision {
namespace {

constexpr int kCoverageCells = 10;  // per image side
constexpr int kMinViews = 3;
constexpr int kMinPointsPerView = 4;

std::string ViewName(std::size_t index) {
  return "view " + std::to_string(index + 1);
}

void CheckViews(const std::vector<CalibrationView>& views, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw InputError(
        "views", 0,
        "image size " + std::to_string(width) + "x" + std::to_string(height) + " is not positive",
        "give the size of the images in pixels");
  }
  for (std::size_t i = 0; i < views.size(); ++i) {
    const CalibrationView& view = views[i];
    if (view.object_points.size() != view.image_points.size()) {
      throw InputError("views", static_cast<int>(i) + 1,
                       ViewName(i) + " has " + std::to_string(view.object_points.size()) +
                           " object points but " + std::to_string(view.image_points.size()) +
                           " image points",
                       "give one image point per object point");
    }
    if (view.object_points.size() < kMinPointsPerView) {
      throw InputError("views", static_cast<int>(i) + 1,
                       ViewName(i) + " has " + std::to_string(view.object_points.size()) +
                           " points; calibration needs at least 4 per view",
                       "drop the view or detect more of the target in it");
    }
    double extent = 0.0;
    for (const Eigen::Vector3d& p : view.object_points) {
      extent = std::max(extent, p.head<2>().cwiseAbs().maxCoeff());
    }
    for (std::size_t k = 0; k < view.object_points.size(); ++k) {
      if (!view.object_points[k].allFinite() || !view.image_points[k].allFinite()) {
        throw InputError("views", static_cast<int>(i) + 1,
                         ViewName(i) + ", point " + std::to_string(k + 1) + " is not finite",
                         "remove or correct the point");
      }
      if (std::abs(view.object_points[k].z()) > 1e-9 * std::max(extent, 1e-300)) {
        throw InputError(
            "views", static_cast<int>(i) + 1,
            ViewName(i) + ", point " + std::to_string(k + 1) +
                " is off the target plane (z = " + std::to_string(view.object_points[k].z()) + ")",
            "calibrate with a planar target whose points have z = 0");
      }
    }
  }
  if (views.size() < kMinViews) {
    throw DegenerateError("the intrinsics from " + std::to_string(views.size()) +
                              " view(s) of a planar target (each view constrains K twice)",
                          "give at least 3 views, better 10 or more, with the target tilted "
                          "differently in each");
  }
}

double Coverage(const std::vector<CalibrationView>& views, int width, int height) {
  std::vector<bool> covered(kCoverageCells * kCoverageCells, false);
  for (const CalibrationView& view : views) {
    for (const Eigen::Vector2d& p : view.image_points) {
      const int cx = static_cast<int>(std::floor(p.x() / width * kCoverageCells));
      const int cy = static_cast<int>(std::floor(p.y() / height * kCoverageCells));
      if (cx < 0 || cy < 0 || cx >= kCoverageCells || cy >= kCoverageCells) continue;
      covered[static_cast<std::size_t>(cy * kCoverageCells + cx)] = true;
    }
  }
  return static_cast<double>(std::count(covered.begin(), covered.end(), true)) /
         static_cast<double>(covered.size());
}

double NormalSpreadDeg(const std::vector<Pose>& T_camera_target) {
  double spread = 0.0;
  for (std::size_t i = 0; i < T_camera_target.size(); ++i) {
    const Eigen::Vector3d ni = T_camera_target[i].linear().col(2);
    for (std::size_t j = i + 1; j < T_camera_target.size(); ++j) {
      const Eigen::Vector3d nj = T_camera_target[j].linear().col(2);
      spread = std::max(spread, std::atan2(ni.cross(nj).norm(), ni.dot(nj)));
    }
  }
  return spread * 180.0 / std::numbers::pi;
}

std::string Format(double value, int precision) {
  std::ostringstream text;
  text.precision(precision);
  text << value;
  return text.str();
}

std::vector<std::string> Warnings(const IntrinsicsResult& result, std::size_t views,
                                  const IntrinsicsOptions& options) {
  std::vector<std::string> warnings;
  if (views < static_cast<std::size_t>(options.recommended_views)) {
    warnings.push_back(
        "only " + std::to_string(views) + " views: the intrinsics rest on few constraints; use " +
        std::to_string(options.recommended_views) + " or more views (10-20 is typical)");
  }
  if (result.normal_spread_deg < options.min_normal_spread_deg) {
    warnings.push_back("the board normals of all views lie within " +
                       Format(result.normal_spread_deg, 3) +
                       " deg of each other: focal length and distance are confounded; tilt the "
                       "board by 20-45 deg in different directions");
  }
  if (result.coverage < options.min_coverage) {
    warnings.push_back("the target points cover only " + Format(100.0 * result.coverage, 3) +
                       "% of the image (10x10 cells): distortion is extrapolated elsewhere; "
                       "show the target near the edges and corners too");
  }
  const IntrinsicsSigma& s = result.sigma;
  const pose::CameraModel& c = result.camera;
  if (s.fx > options.max_focal_sigma_relative * c.fx ||
      s.fy > options.max_focal_sigma_relative * c.fy) {
    warnings.push_back("the focal length is poorly determined (1 sigma: fx " + Format(s.fx, 3) +
                       " px, fy " + Format(s.fy, 3) +
                       " px): add views at different tilts and distances");
  }
  if (s.cx > options.max_principal_sigma_px || s.cy > options.max_principal_sigma_px) {
    warnings.push_back("the principal point is poorly determined (1 sigma: cx " + Format(s.cx, 3) +
                       " px, cy " + Format(s.cy, 3) +
                       " px): add views with the board tilted about both image axes");
  }
  return warnings;
}

}  // namespace

bool IntrinsicsOptions::IsValid(std::string* why) const {
  if (recommended_views < 0) {
    return Invalid(why, "IntrinsicsOptions.recommended_views",
                   "must be 0 or more, got " + std::to_string(recommended_views),
                   "give the number of views below which to warn (default 5)");
  }
  if (!(min_normal_spread_deg >= 0.0 && min_normal_spread_deg <= 180.0)) {
    return Invalid(why, "IntrinsicsOptions.min_normal_spread_deg", "must be 0 … 180 degrees",
                   "give the smallest spread of board normals to accept (default 10)");
  }
  if (!(min_coverage >= 0.0 && min_coverage <= 1.0)) {
    return Invalid(why, "IntrinsicsOptions.min_coverage", "must be a fraction 0 … 1",
                   "give the share of image cells the points must reach (default 0.5)");
  }
  if (!(max_focal_sigma_relative > 0.0) || !std::isfinite(max_focal_sigma_relative)) {
    return Invalid(why, "IntrinsicsOptions.max_focal_sigma_relative",
                   "must be a finite number above 0", "give σ(f)/f to accept (default 0.005)");
  }
  if (!(max_principal_sigma_px > 0.0) || !std::isfinite(max_principal_sigma_px)) {
    return Invalid(why, "IntrinsicsOptions.max_principal_sigma_px",
                   "must be a finite number of pixels above 0",
                   "give the principal point σ to accept (default 5)");
  }
  return true;
}

IntrinsicsResult CalibrateIntrinsics(const std::vector<CalibrationView>& views, int width,
                                     int height, const IntrinsicsOptions& options) {
  RequireValid(options);
  CheckViews(views, width, height);

  // calibrateCamera takes single-precision points (its input check asks for CV_32F).
  std::vector<std::vector<cv::Point3f>> object(views.size());
  std::vector<std::vector<cv::Point2f>> image(views.size());
  for (std::size_t i = 0; i < views.size(); ++i) {
    for (std::size_t k = 0; k < views[i].object_points.size(); ++k) {
      const Eigen::Vector3d& p = views[i].object_points[k];
      const Eigen::Vector2d& q = views[i].image_points[k];
      object[i].emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()), 0.0f);
      image[i].emplace_back(static_cast<float>(q.x()), static_cast<float>(q.y()));
    }
  }
  int flags = 0;
  if (options.fix_k3) flags |= cv::CALIB_FIX_K3;
  if (options.fix_aspect_ratio) flags |= cv::CALIB_FIX_ASPECT_RATIO;  // ratio of K below: 1
  cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
  cv::Mat distortion = cv::Mat::zeros(5, 1, CV_64F);
  std::vector<cv::Mat> rvecs, tvecs;
  cv::Mat sigma_intrinsics, sigma_extrinsics, view_errors;
  double rms = 0.0;
  try {
    rms = cv::calibrateCamera(object, image, cv::Size(width, height), K, distortion, rvecs, tvecs,
                              sigma_intrinsics, sigma_extrinsics, view_errors, flags);
  } catch (const cv::Exception& e) {
    throw DegenerateError("the intrinsics (OpenCV calibrateCamera failed: " + e.err + ")",
                          "give views with the target tilted differently in each");
  }

  IntrinsicsResult result;
  result.rms_px = rms;
  pose::CameraModel& camera = result.camera;
  camera.fx = K.at<double>(0, 0);
  camera.fy = K.at<double>(1, 1);
  camera.cx = K.at<double>(0, 2);
  camera.cy = K.at<double>(1, 2);
  camera.width = width;
  camera.height = height;
  for (int k = 0; k < 5; ++k)
    camera.distortion[static_cast<std::size_t>(k)] = distortion.at<double>(k);
  result.sigma.fy = sigma_intrinsics.at<double>(1);
  // With a fixed aspect ratio fx follows fy (OpenCV then reports σ(fx) = 0).
  result.sigma.fx = options.fix_aspect_ratio ? result.sigma.fy * camera.fx / camera.fy
                                             : sigma_intrinsics.at<double>(0);
  result.sigma.cx = sigma_intrinsics.at<double>(2);
  result.sigma.cy = sigma_intrinsics.at<double>(3);
  for (int k = 0; k < 5; ++k) {
    result.sigma.distortion[static_cast<std::size_t>(k)] = sigma_intrinsics.at<double>(4 + k);
  }
  bool finite = std::isfinite(rms) && cv::checkRange(K) && cv::checkRange(distortion);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const cv::Vec3d r(rvecs[i]), t(tvecs[i]);
    result.T_camera_target.push_back(
        MakePose(so3::Exp(Eigen::Vector3d(r[0], r[1], r[2])), Eigen::Vector3d(t[0], t[1], t[2])));
    result.view_rms_px.push_back(view_errors.at<double>(static_cast<int>(i)));
    finite = finite && result.T_camera_target.back().matrix().allFinite();
  }
  if (!finite) {
    throw DegenerateError("the intrinsics (OpenCV calibrateCamera returned non-finite values)",
                          "give views with the target tilted differently in each");
  }
  result.coverage = Coverage(views, width, height);
  result.normal_spread_deg = NormalSpreadDeg(result.T_camera_target);
  result.warnings = Warnings(result, views.size(), options);
  return result;
}

}  // namespace hecal::vision
