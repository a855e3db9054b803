// The perspective forward model of the contour studies: see perspective_view.h.
#include "hecal/contour/perspective_view.h"

#include <cmath>
#include <string>

#include "hecal/core/error.h"
#include "hecal/geometry/euler.h"

namespace hecal::contour {

Eigen::Matrix2Xd ProjectPerspective(const Eigen::Matrix2Xd& plane_points,
                                    const Eigen::Matrix3d& rotation,
                                    const Eigen::Vector3d& translation,
                                    const ContourCamera& camera) {
  const Eigen::Vector3d offset(translation.x(), translation.y(), camera.z0 + translation.z());
  Eigen::Matrix2Xd image(2, plane_points.cols());
  for (Eigen::Index i = 0; i < plane_points.cols(); ++i) {
    const Eigen::Vector3d x =
        rotation.leftCols<2>() * plane_points.col(i) + offset;  // p = (px, py, 0)
    if (!(x.z() > 0.0)) {
      throw DegenerateError(
          "the contour: target point " + std::to_string(i) + " is not in front of the camera",
          "keep the target in front of the camera (smaller motion)");
    }
    image.col(i) = camera.focal * x.head<2>() / x.z();
  }
  return image;
}

Eigen::Matrix2Xd TemplateImage(const Eigen::Matrix2Xd& plane_points, const ContourCamera& camera) {
  return camera.focal / camera.z0 * plane_points;
}

Eigen::Matrix3d RotationZyx(double rx, double ry, double rz) {
  return MatrixFromEuler(Eigen::Vector3d(rz, ry, rx), *EulerSequence::Parse("ZYX"));
}

}  // namespace hecal::contour
