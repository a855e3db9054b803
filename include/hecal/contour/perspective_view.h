// The forward model of the contour studies and tests (docs/contour.md#the-experiments): a planar
// target seen by a true pinhole camera, so the weak-perspective error of affine_pose.h is real in
// every result.
//
// The target is a closed B-spline in its own plane (z = 0, coordinates in the unit of Z0). The
// motion (R, T) is the one of affine_pose.h: x_camera = R p + (Tx, Ty, Z0 + Tz), and the image
// (relative to the principal point, in the unit of f) is f (x/z, y/z). In the initial view
// (R = I, T = 0) this is exactly weak perspective, d = f p / Z0, so the template is exact.
// Control points are projected as points — what the paper does when it adds pixel noise "to the
// projected control points"; a perspective image of a B-spline is not exactly the B-spline of
// the projected control points, which is part of the model error studied.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "hecal/contour/affine_pose.h"

namespace hecal::contour {

// Perspective image of target-plane points (2 × M) after the motion. Throws
// hecal::DegenerateError when a point is not in front of the camera (z ≤ 0).
Eigen::Matrix2Xd ProjectPerspective(const Eigen::Matrix2Xd& plane_points,
                                    const Eigen::Matrix3d& rotation,
                                    const Eigen::Vector3d& translation,
                                    const ContourCamera& camera);

// The initial (template) image of target-plane points: f p / Z0.
Eigen::Matrix2Xd TemplateImage(const Eigen::Matrix2Xd& plane_points, const ContourCamera& camera);

// A rotation from the paper's roll–pitch–yaw angles (radians): Rz(rz) Ry(ry) Rx(rx).
Eigen::Matrix3d RotationZyx(double rx, double ry, double rz);

}  // namespace hecal::contour
