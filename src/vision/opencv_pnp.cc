#include "hecal/vision/opencv_pnp.h"

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <stdexcept>
#include <string>

#include "hecal/core/error.h"
#include "hecal/geometry/dense_decompositions.h"
#include "hecal/geometry/so3.h"

namespace hecal::vision {
namespace {

constexpr std::array<PnpMethodInfo, 4> kMethods = {{
    {PnpMethod::kIppe, "ippe",
     "OpenCV IPPE (Collins & Bartoli 2014): closed form for coplanar points, n >= 4", 4, true},
    {PnpMethod::kSqpnp, "sqpnp",
     "OpenCV SQPnP (Terzakis & Lourakis 2020): globally optimal, planar or not, n >= 3", 3, false},
    {PnpMethod::kEpnp, "epnp", "OpenCV EPnP (Lepetit et al. 2009): linear O(n), n >= 4", 4, false},
    {PnpMethod::kIterative, "iterative",
     "OpenCV ITERATIVE: Levenberg-Marquardt from a homography (planar) or DLT (n >= 6)", 4, false},
}};

// Relative tolerance of the coplanarity and collinearity tests (see the header).
constexpr double kFlatness = 1e-6;

int OpenCvFlag(PnpMethod method) {
  switch (method) {
    case PnpMethod::kIppe:
      return cv::SOLVEPNP_IPPE;
    case PnpMethod::kSqpnp:
      return cv::SOLVEPNP_SQPNP;
    case PnpMethod::kEpnp:
      return cv::SOLVEPNP_EPNP;
    case PnpMethod::kIterative:
      return cv::SOLVEPNP_ITERATIVE;
  }
  throw std::invalid_argument("unknown PnP method");
}

// Singular values of the centred points (descending), the unit normal of their least-squares
// plane (the last right singular vector), the largest distance from that plane and the
// largest distance from the centroid (the extent).
struct Shape {
  Eigen::Vector3d singular_values = Eigen::Vector3d::Zero();
  double plane_distance = 0.0;
  double extent = 0.0;
};

Shape AnalyseShape(const std::vector<Eigen::Vector3d>& points) {
  Shape shape;
  if (points.empty()) return shape;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Eigen::MatrixXd centred(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t k = 0; k < points.size(); ++k) {
    centred.row(static_cast<Eigen::Index>(k)) = (points[k] - centroid).transpose();
    shape.extent = std::max(shape.extent, (points[k] - centroid).norm());
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeThinV);
  shape.singular_values.head(svd.singularValues().size()) = svd.singularValues();
  const Eigen::Vector3d normal = svd.matrixV().col(2);
  shape.plane_distance = (centred * normal).cwiseAbs().maxCoeff();
  return shape;
}

std::string MethodSource(PnpMethod method) {
  return "PnpMethod " + std::string(Info(method).name);
}

void CheckInput(PnpMethod method, const std::vector<Eigen::Vector3d>& object_points,
                const std::vector<Eigen::Vector2d>& pixels, const pose::CameraModel& camera,
                bool has_initial) {
  if (object_points.size() != pixels.size()) {
    throw InputError("object points", 0,
                     std::to_string(object_points.size()) + " object points but " +
                         std::to_string(pixels.size()) + " image points",
                     "give one image point per object point, in the same order");
  }
  for (std::size_t k = 0; k < object_points.size(); ++k) {
    if (!object_points[k].allFinite() || !pixels[k].allFinite()) {
      throw InputError("object points", static_cast<int>(k) + 1,
                       "point " + std::to_string(k + 1) + " is not finite (NaN or Inf)",
                       "remove or correct the point");
    }
  }
  if (!(camera.fx > 0.0) || !(camera.fy > 0.0) || !std::isfinite(camera.cx) ||
      !std::isfinite(camera.cy)) {
    throw InputError("camera", 0, "the focal lengths must be positive and finite",
                     "give fx, fy > 0 and a finite principal point");
  }
  for (double d : camera.distortion) {
    if (!std::isfinite(d)) {
      throw InputError("camera", 0, "a distortion coefficient is not finite",
                       "give finite k1, k2, p1, p2, k3");
    }
  }
  const PnpMethodInfo& info = Info(method);
  if (object_points.size() < static_cast<std::size_t>(info.min_points)) {
    throw InputError(MethodSource(method), 0,
                     std::string(info.name) + " needs at least " + std::to_string(info.min_points) +
                         " points, got " + std::to_string(object_points.size()),
                     "give more point correspondences");
  }
  const Shape shape = AnalyseShape(object_points);
  if (shape.singular_values(1) <= kFlatness * shape.singular_values(0)) {
    throw DegenerateError("the camera pose: the object points lie on one line",
                          "use at least 4 object points that span a plane or a volume");
  }
  const bool planar = shape.plane_distance <= kFlatness * shape.extent;
  if (info.planar_only && !planar) {
    throw InputError(MethodSource(method), 0,
                     std::string(info.name) + " needs coplanar object points, but they are up to " +
                         std::to_string(shape.plane_distance) +
                         " (object units) off their best-fit plane",
                     "use sqpnp, epnp or iterative for non-planar points");
  }
  if (method == PnpMethod::kIterative && !planar && !has_initial && object_points.size() < 6) {
    throw InputError(MethodSource(method), 0,
                     "iterative needs at least 6 non-coplanar points to start (DLT), got " +
                         std::to_string(object_points.size()),
                     "give 6 or more points, or use sqpnp");
  }
}

Pose PoseFromRvecTvec(const cv::Vec3d& rvec, const cv::Vec3d& tvec) {
  return MakePose(so3::Exp(Eigen::Vector3d(rvec[0], rvec[1], rvec[2])),
                  Eigen::Vector3d(tvec[0], tvec[1], tvec[2]));
}

}  // namespace

std::span<const PnpMethodInfo> OpenCvPnpMethods() {
  return kMethods;
}

const PnpMethodInfo& Info(PnpMethod method) {
  for (const PnpMethodInfo& info : kMethods) {
    if (info.method == method) return info;
  }
  throw std::invalid_argument("unknown PnP method");
}

std::optional<PnpMethod> ParsePnpMethod(std::string_view name) {
  for (const PnpMethodInfo& info : kMethods) {
    if (info.name == name) return info.method;
  }
  return std::nullopt;
}

bool AreCoplanar(const std::vector<Eigen::Vector3d>& points) {
  const Shape shape = AnalyseShape(points);
  return shape.plane_distance <= kFlatness * shape.extent;
}

Pose SolvePnPOpenCv(PnpMethod method, const std::vector<Eigen::Vector3d>& object_points,
                    const std::vector<Eigen::Vector2d>& pixels, const pose::CameraModel& camera,
                    const std::optional<Pose>& initial) {
  if (initial.has_value() && method != PnpMethod::kIterative) {
    throw std::invalid_argument("SolvePnPOpenCv: an initial pose is used by iterative only");
  }
  CheckInput(method, object_points, pixels, camera, initial.has_value());

  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  object.reserve(object_points.size());
  image.reserve(pixels.size());
  for (std::size_t k = 0; k < object_points.size(); ++k) {
    object.emplace_back(object_points[k].x(), object_points[k].y(), object_points[k].z());
    image.emplace_back(pixels[k].x(), pixels[k].y());
  }
  const cv::Matx33d K(camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0);
  const cv::Vec<double, 5> distortion(camera.distortion.data());

  cv::Vec3d rvec, tvec;
  if (initial.has_value()) {
    const Eigen::Vector3d w = so3::Log(initial->linear());
    rvec = cv::Vec3d(w.x(), w.y(), w.z());
    tvec = cv::Vec3d(initial->translation().x(), initial->translation().y(),
                     initial->translation().z());
  }
  const bool solved = cv::solvePnP(object, image, K, distortion, rvec, tvec, initial.has_value(),
                                   OpenCvFlag(method));
  const Pose T_camera_target = PoseFromRvecTvec(rvec, tvec);
  if (!solved || !T_camera_target.matrix().allFinite()) {
    throw DegenerateError(
        "the camera pose (OpenCV " + std::string(Info(method).name) + " found no solution)",
        "check that the image points belong to the object points, in order");
  }
  return T_camera_target;
}

Pose SolvePnPOpenCvRefined(const std::vector<Eigen::Vector3d>& object_points,
                           const std::vector<Eigen::Vector2d>& pixels,
                           const pose::CameraModel& camera) {
  const PnpMethod closed_form = AreCoplanar(object_points) ? PnpMethod::kIppe : PnpMethod::kSqpnp;
  const Pose start = SolvePnPOpenCv(closed_form, object_points, pixels, camera);
  return SolvePnPOpenCv(PnpMethod::kIterative, object_points, pixels, camera, start);
}

}  // namespace hecal::vision
