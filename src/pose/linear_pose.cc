// the linear pose paper's method (see linear_pose.h for the method, its equations and edge cases).
#include "hecal/pose/linear_pose.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "hecal/core/error.h"
#include "hecal/core/number_text.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/dense_decompositions.h"
#include "hecal/geometry/nearest_rotation.h"

namespace hecal::pose {
namespace {

constexpr std::size_t kMinLinearPosePoints = 6;
// U's reciprocal condition number below which it is numerically singular.
constexpr double kSingular = 1e-12;

// g = U⁺ B with the first point as P1, and U's reciprocal condition number.
struct SeedSystem {
  Eigen::Matrix<double, 9, 1> g = Eigen::Matrix<double, 9, 1>::Zero();
  double reciprocal_condition = 0.0;
};

SeedSystem SolveSeedSystem(const std::vector<Eigen::Vector3d>& object_points,
                           const std::vector<Eigen::Vector2d>& normalized) {
  const Eigen::Index rows = 2 * static_cast<Eigen::Index>(object_points.size() - 1);
  // Dynamic-size, so that the SVD is the one compiled in dense_decompositions.h.
  Eigen::MatrixXd U = Eigen::MatrixXd::Zero(rows, 9);
  Eigen::VectorXd B(rows);
  const Eigen::Vector2d& ref = normalized[0];
  Eigen::Index row = 0;
  for (std::size_t k = 1; k < object_points.size(); ++k) {
    const Eigen::RowVector3d P = (object_points[k] - object_points[0]).transpose();
    const Eigen::Vector2d& p = normalized[k];
    U.block<1, 3>(row, 0) = P;
    U.block<1, 3>(row, 6) = -p.x() * P;
    B(row++) = p.x() - ref.x();
    U.block<1, 3>(row, 3) = P;
    U.block<1, 3>(row, 6) = -p.y() * P;
    B(row++) = p.y() - ref.y();
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(U, Eigen::ComputeThinU | Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  SeedSystem system;
  system.reciprocal_condition = sigma(0) > 0.0 ? sigma(8) / sigma(0) : 0.0;
  if (system.reciprocal_condition >= kSingular) system.g = svd.solve(B);
  return system;
}

// Thickness σ3/σ1 of points with scatter S (singular values squared); 0 for a point or a line.
double Thickness(const Eigen::Matrix3d& scatter) {
  const Eigen::Vector3d eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter, Eigen::EigenvaluesOnly).eigenvalues();
  return eigenvalues(2) > 0.0 ? std::sqrt(std::max(eigenvalues(0), 0.0) / eigenvalues(2)) : 0.0;
}

}  // namespace

bool PointSpread::Coplanar(double tolerance) const {
  return singular_values(2) <= tolerance * singular_values(0);
}

bool PointSpread::Collinear(double tolerance) const {
  return singular_values(1) <= tolerance * singular_values(0);
}

PointSpread AnalyseSpread(const std::vector<Eigen::Vector3d>& points) {
  PointSpread spread;
  if (points.empty()) return spread;
  for (const Eigen::Vector3d& p : points) spread.centroid += p;
  spread.centroid /= static_cast<double>(points.size());
  for (const Eigen::Vector3d& p : points) {
    spread.scatter.noalias() += (p - spread.centroid) * (p - spread.centroid).transpose();
  }
  // The scatter's eigenvalues (ascending) are the squared singular values of the centred points.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(spread.scatter);
  for (int i = 0; i < 3; ++i) {
    spread.singular_values(i) = std::sqrt(std::max(eigen.eigenvalues()(2 - i), 0.0));
    spread.axes.col(i) = eigen.eigenvectors().col(2 - i);
  }
  if (spread.axes.determinant() < 0.0) spread.axes.col(2) *= -1.0;
  return spread;
}

std::optional<std::size_t> LonePointOffAPlane(const std::vector<Eigen::Vector3d>& points,
                                              const PointSpread& spread, double tolerance) {
  const double n = static_cast<double>(points.size());
  if (points.size() < 2 || spread.Coplanar(tolerance)) return std::nullopt;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const Eigen::Vector3d d = points[j] - spread.centroid;
    if (Thickness(spread.scatter - n / (n - 1.0) * d * d.transpose()) <= tolerance) return j;
  }
  return std::nullopt;
}

void CheckCorrespondences(const std::vector<Eigen::Vector3d>& object_points,
                          const std::vector<Eigen::Vector2d>& image_points) {
  if (object_points.size() != image_points.size()) {
    throw InputError("image points", 0,
                     std::to_string(object_points.size()) + " object points but " +
                         std::to_string(image_points.size()) + " image points",
                     "give one image point per object point, in the same order");
  }
  for (std::size_t k = 0; k < object_points.size(); ++k) {
    if (!object_points[k].allFinite() || !image_points[k].allFinite()) {
      throw InputError("image points", 0,
                       "point " + std::to_string(k + 1) + " is not finite (NaN or Inf)",
                       "remove or correct the point");
    }
  }
}

bool LinearPoseOptions::IsValid(std::string* why) const {
  if (planarity_tolerance > 0.0 && planarity_tolerance < 1.0) return true;
  return Invalid(why, "LinearPoseOptions.planarity_tolerance",
                 "must be above 0 and below 1, got " + NumberText(planarity_tolerance, 3),
                 "use e.g. 1e-3 (the smallest spread of a plane relative to the largest)");
}

LinearPoseResult LinearPoseNormalized(const std::vector<Eigen::Vector3d>& object_points,
                                      const std::vector<Eigen::Vector2d>& normalized,
                                      const LinearPoseOptions& options) {
  RequireValid(options);
  CheckCorrespondences(object_points, normalized);
  const std::size_t n = object_points.size();
  if (n < kMinLinearPosePoints) {
    throw DegenerateError(
        "the camera pose with the linear method (linear): it needs at least 6 "
        "non-coplanar points, got " +
            std::to_string(n),
        "give 6 or more points off one plane, or use --method sqpnp (3 or "
        "more points) or ippe (4 or more coplanar points)");
  }
  const PointSpread spread = AnalyseSpread(object_points);
  if (spread.Coplanar(options.planarity_tolerance)) {
    throw DegenerateError(
        "the camera pose with the linear method (linear): it needs non-coplanar object "
        "points, but these lie on one plane (thickness/extent " +
            NumberText(spread.singular_values(2) / spread.singular_values(0), 3) + ")",
        "for a planar target use --method ippe or dlt (homography)");
  }

  if (const std::optional<std::size_t> lone =
          LonePointOffAPlane(object_points, spread, options.planarity_tolerance)) {
    throw DegenerateError(
        "the camera pose with the linear method (linear): all object points but point " +
            std::to_string(*lone + 1) + " lie on one plane, which leaves its system singular",
        "add at least one more point off that plane, or use --method ippe or "
        "dlt on the planar points alone");
  }
  const SeedSystem system = SolveSeedSystem(object_points, normalized);
  if (system.reciprocal_condition < kSingular) {
    throw DegenerateError(
        "the camera pose with the linear method (linear): its system U is numerically "
        "singular (reciprocal condition " +
            NumberText(system.reciprocal_condition, 3) +
            "): the points and the camera are in a critical configuration",
        "use points spread through a volume, or --method dlt / sqpnp");
  }

  const double g_norm = system.g.norm();
  const double a = std::sqrt(3.0) / g_norm;
  if (!(g_norm > 0.0) || !std::isfinite(a)) {
    throw DegenerateError(
        "the camera pose with the linear method (linear): the depth of the first point "
        "(all image points coincide with it)",
        "check the image points; the object must have an extent in the image");
  }
  const Eigen::Matrix3d R_estimate =
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(system.g.data()) * a;
  const Eigen::Matrix3d R = NearestRotationQuaternion(R_estimate);
  const Eigen::Vector3d T_prime = a * normalized[0].homogeneous();  // T' on P1's ray

  LinearPoseResult result;
  result.T_camera_target = MakePose(R, T_prime - R * object_points[0]);
  result.reciprocal_condition = system.reciprocal_condition;
  result.rotation_residual = (R_estimate - R).norm() / std::sqrt(3.0);
  return result;
}

LinearPoseResult LinearPose(const std::vector<Eigen::Vector3d>& object_points,
                            const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                            const LinearPoseOptions& options) {
  CheckCorrespondences(object_points, pixels);
  return LinearPoseNormalized(object_points, UndistortPoints(camera, pixels), options);
}

}  // namespace hecal::pose
