// The normalised DLT and the planar homography path (see dlt_pose.h for both methods).
#include "hecal/pose/dlt_pose.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <string>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/dense_decompositions.h"
#include "hecal/geometry/nearest_rotation.h"
#include "hecal/pose/linear_pose.h"

namespace hecal::pose {
namespace {

constexpr std::size_t kMinProjective = 6;
constexpr std::size_t kMinHomography = 4;
// A second-smallest singular value of A below this fraction of the largest: the null space is
// not one-dimensional.
constexpr double kNullSpaceGap = 1e-6;

// Hartley's normalising similarity x̃ = scale (x − centroid): centroid at the origin, mean
// distance √D from it.
template <int D>
struct Normalisation {
  Eigen::Matrix<double, D, 1> centroid = Eigen::Matrix<double, D, 1>::Zero();
  double scale = 1.0;

  Eigen::Matrix<double, D + 1, 1> Apply(const Eigen::Matrix<double, D, 1>& x) const {
    return (scale * (x - centroid)).homogeneous();
  }
  // The (D+1)×(D+1) matrix of the similarity and of its inverse.
  Eigen::Matrix<double, D + 1, D + 1> Matrix() const {
    Eigen::Matrix<double, D + 1, D + 1> T = Eigen::Matrix<double, D + 1, D + 1>::Identity();
    T.template topLeftCorner<D, D>() *= scale;
    T.template topRightCorner<D, 1>() = -scale * centroid;
    return T;
  }
  Eigen::Matrix<double, D + 1, D + 1> Inverse() const {
    Eigen::Matrix<double, D + 1, D + 1> T = Eigen::Matrix<double, D + 1, D + 1>::Identity();
    T.template topLeftCorner<D, D>() /= scale;
    T.template topRightCorner<D, 1>() = centroid;
    return T;
  }
};

template <int D>
Normalisation<D> Normalise(const std::vector<Eigen::Matrix<double, D, 1>>& points) {
  Normalisation<D> n;
  for (const auto& p : points) n.centroid += p;
  n.centroid /= static_cast<double>(points.size());
  double mean_distance = 0.0;
  for (const auto& p : points) mean_distance += (p - n.centroid).norm();
  mean_distance /= static_cast<double>(points.size());
  n.scale = mean_distance > 0.0 ? std::sqrt(static_cast<double>(D)) / mean_distance : 1.0;
  return n;
}

// The unit vector h minimising ‖A h‖ for A with rows [Xₕᵀ 0 −x Xₕᵀ], [0 Xₕᵀ −y Xₕᵀ] over the
// (normalised) correspondences Xₕ ↔ (x, y): A's last right singular vector.
template <int C>
Eigen::Matrix<double, 3 * C, 1> SolveDlt(const std::vector<Eigen::Matrix<double, C, 1>>& object,
                                         const std::vector<Eigen::Vector2d>& image,
                                         const std::string& what) {
  // Dynamic-size, so that the SVD is the one compiled in dense_decompositions.h.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * static_cast<Eigen::Index>(object.size()), 3 * C);
  for (std::size_t k = 0; k < object.size(); ++k) {
    for (int axis = 0; axis < 2; ++axis) {
      const Eigen::Index row = 2 * static_cast<Eigen::Index>(k) + axis;
      A.row(row).template segment<C>(axis * C) = object[k].transpose();
      A.row(row).template segment<C>(2 * C) = -image[k](axis) * object[k].transpose();
    }
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  // Descending; min(2N, 3C) of them: for 4 points on a plane (8 × 9) the ninth, zero, is implicit.
  const auto& sigma = svd.singularValues();
  if (!(sigma(3 * C - 2) > kNullSpaceGap * sigma(0))) {
    throw DegenerateError(what +
                              ": the linear system has more than one solution (the points "
                              "are in a degenerate configuration, e.g. three of four "
                              "coplanar points on one line)",
                          "use more points, spread over the target");
  }
  return svd.matrixV().col(3 * C - 1);
}

DltPoseResult ProjectivePose(const std::vector<Eigen::Vector3d>& object_points,
                             const std::vector<Eigen::Vector2d>& normalized) {
  const Normalisation<3> object_norm = Normalise<3>(object_points);
  const Normalisation<2> image_norm = Normalise<2>(normalized);
  std::vector<Eigen::Vector4d> object;
  std::vector<Eigen::Vector2d> image;
  for (std::size_t k = 0; k < object_points.size(); ++k) {
    object.push_back(object_norm.Apply(object_points[k]));
    image.push_back(image_norm.Apply(normalized[k]).head<2>());
  }
  const Eigen::Matrix<double, 12, 1> p = SolveDlt<4>(object, image, "the camera pose (DLT)");
  const Eigen::Matrix<double, 3, 4> P =
      image_norm.Inverse() *
      Eigen::Map<const Eigen::Matrix<double, 3, 4, Eigen::RowMajor>>(p.data()) *
      object_norm.Matrix();

  const Eigen::Matrix3d M = P.leftCols<3>();
  const double depth_sign = M.row(2).dot(object_norm.centroid) + P(2, 3) >= 0.0 ? 1.0 : -1.0;
  // Singular values of M as the square roots of MᵀM's eigenvalues.
  const Eigen::Vector3d squared =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(M.transpose() * M, Eigen::EigenvaluesOnly)
          .eigenvalues();
  const double lambda = depth_sign * squared.cwiseMax(0.0).cwiseSqrt().mean();
  DltPoseResult result;
  result.T_camera_target = MakePose(NearestRotationSvd(M / lambda), P.col(3) / lambda);
  result.path = DltPath::kProjective;
  return result;
}

DltPoseResult HomographyPose(const std::vector<Eigen::Vector3d>& object_points,
                             const std::vector<Eigen::Vector2d>& normalized,
                             const PointSpread& spread) {
  std::vector<Eigen::Vector2d> plane;
  for (const Eigen::Vector3d& X : object_points) {
    plane.push_back(spread.axes.leftCols<2>().transpose() * (X - spread.centroid));
  }
  const Normalisation<2> plane_norm = Normalise<2>(plane);
  const Normalisation<2> image_norm = Normalise<2>(normalized);
  std::vector<Eigen::Vector3d> object;
  std::vector<Eigen::Vector2d> image;
  for (std::size_t k = 0; k < plane.size(); ++k) {
    object.push_back(plane_norm.Apply(plane[k]));
    image.push_back(image_norm.Apply(normalized[k]).head<2>());
  }
  const Eigen::Matrix<double, 9, 1> h =
      SolveDlt<3>(object, image, "the camera pose (DLT homography)");
  const Eigen::Matrix3d H =
      image_norm.Inverse() *
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(h.data()) *
      plane_norm.Matrix();

  const double lambda = (H(2, 2) >= 0.0 ? 1.0 : -1.0) * 0.5 * (H.col(0).norm() + H.col(1).norm());
  const Eigen::Vector3d r1 = H.col(0) / lambda;
  const Eigen::Vector3d r2 = H.col(1) / lambda;
  Eigen::Matrix3d R_plane;
  R_plane << r1, r2, r1.cross(r2);
  const Eigen::Matrix3d R = NearestRotationSvd(R_plane) * spread.axes.transpose();
  DltPoseResult result;
  result.T_camera_target = MakePose(R, H.col(2) / lambda - R * spread.centroid);
  result.path = DltPath::kHomography;
  return result;
}

}  // namespace

std::string_view DltPathName(DltPath path) {
  return path == DltPath::kProjective ? "projective DLT" : "homography";
}

bool DltPoseOptions::IsValid(std::string* why) const {
  if (planarity_tolerance > 0.0 && planarity_tolerance < 1.0) return true;
  return Invalid(why, "DltPoseOptions.planarity_tolerance",
                 "must be above 0 and below 1, got " + std::to_string(planarity_tolerance),
                 "use e.g. 1e-3 (the smallest spread of a plane relative to the largest)");
}

DltPoseResult DltPoseNormalized(const std::vector<Eigen::Vector3d>& object_points,
                                const std::vector<Eigen::Vector2d>& normalized,
                                const DltPoseOptions& options) {
  RequireValid(options);
  CheckCorrespondences(object_points, normalized);
  const std::size_t n = object_points.size();
  const PointSpread spread = AnalyseSpread(object_points);
  if (n >= 2 && spread.Collinear(options.planarity_tolerance)) {
    throw DegenerateError("the camera pose (DLT): the object points lie on one line",
                          "use points that span a plane (4 or more) or a volume (6 or more)");
  }
  if (const std::optional<std::size_t> lone =
          LonePointOffAPlane(object_points, spread, options.planarity_tolerance)) {
    throw DegenerateError("the camera pose (DLT): all object points but point " +
                              std::to_string(*lone + 1) +
                              " lie on one plane (8 + 2 constraints for the DLT's 11 unknowns)",
                          "add at least one more point off that plane, or leave the lone point "
                          "out to use the homography");
  }
  const bool planar = spread.Coplanar(options.planarity_tolerance);
  if (n < (planar ? kMinHomography : kMinProjective)) {
    throw DegenerateError(
        "the camera pose (DLT): it needs at least 6 non-coplanar points, or 4 "
        "coplanar ones (homography), got " +
            std::to_string(n) + (planar ? " coplanar" : " non-coplanar"),
        "give more points, or use --method sqpnp (3 or more points)");
  }
  return planar ? HomographyPose(object_points, normalized, spread)
                : ProjectivePose(object_points, normalized);
}

DltPoseResult DltPose(const std::vector<Eigen::Vector3d>& object_points,
                      const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                      const DltPoseOptions& options) {
  CheckCorrespondences(object_points, pixels);
  return DltPoseNormalized(object_points, UndistortPoints(camera, pixels), options);
}

}  // namespace hecal::pose
