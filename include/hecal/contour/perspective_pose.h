// The camera motion of a contour without weak perspective's bias (an extension of
// docs/contour.md#motion-from-an-affinity).
//
// PoseFromShape inverts the weak-perspective model exactly, so on a true pinhole image it is
// biased: the best affine fit of a perspective image is not the weak-perspective affinity of the
// motion (the paper's "spurious Ty" under a rotation about x is one face of this). The bias
// grows with the target's size over its distance and with the tilt, and for a well-tracked
// contour it is many standard deviations (docs: with the paper's target at 5 m and 20° of tilt,
// 0.8 px at the rim; Tx off by 30σ).
//
// PerspectivePoseModel::Pose removes it. The template (the first view, image coordinates
// relative to the principal point) is taken, as in the paper, as the fronto-parallel view of the
// target at distance Z0, so the target's own curve is template · Z0/f. Let A(R, T) be the
// affine fit the tracker (shape_tracker.h) converges to on the true perspective image of that
// curve after the motion: the least-squares fit of the normal distances from the affine curve's
// samples (`samples_per_span`, the tracker's points_per_span) to the projected outline. (Fitting
// corresponding points instead differs by the tangential part of the non-affine displacement:
// tens of the tracker's σ.) For a measured shape
// vector S the pose solves A(R, T) = S — six equations, six unknowns — by Newton's method from
// the weak-perspective pose, with R updated as R Exp(ω) (right perturbation) and the Jacobian by
// central differences; it converges in 2–4 iterations to 1e-10 px.
// The Necker pair: perspective does tell the two members apart, but only through the part of the
// image an affinity discards, so both members have a root of A = S. hecal returns the root in the
// rotation form's range (affine_pose.h: zyx Rx + Ry ≥ 0, zxz φ ∈ [0, π)), starting Newton from
// the weak pose and, when that root is out of range, from its mirror. Near the boundary of the
// range (zero tilt; φ near 0 or π) both roots can fall just outside; the first is then kept and
// its Euler angles reported as they are.
// Needs the true principal point and a first view that is fronto-parallel; the tracked S must be
// the fit of the same curve.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/bspline.h"
#include "hecal/contour/shape_space.h"
#include "hecal/geometry/types.h"

namespace hecal::contour {

class PerspectivePoseModel {
 public:
  // `template_points`: the control points of the first view's contour, image coordinates
  // relative to the principal point (the unit of f) — the tracker's template. Throws like
  // ShapeSpace for a degenerate contour and hecal::InputError for an invalid camera.
  PerspectivePoseModel(const Eigen::Matrix2Xd& template_points, const ContourCamera& camera,
                       int samples_per_span = 8);

  // A(p): the affine fit of the perspective image after the motion (R, T).
  Vector6d PerspectiveShape(const Eigen::Matrix3d& rotation,
                            const Eigen::Vector3d& translation) const;

  // The pose whose perspective image has the affine fit `shape` (above). Throws
  // hecal::DegenerateError for a singular shape or when the iteration does not converge in
  // `max_iterations` (the target would be behind the camera, or the tilt near 90°).
  ContourPose Pose(const Vector6d& shape, RotationForm form, int max_iterations = 50) const;

  const ContourCamera& camera() const { return camera_; }

 private:
  std::optional<ContourPose> Newton(const Vector6d& shape, Eigen::Matrix3d R, Eigen::Vector3d T,
                                    RotationForm form, int max_iterations) const;

  ContourCamera camera_;
  ClosedBSpline target_;  // the target's curve in its plane (Z0's unit)
  ShapeSpace space_;      // on the template's control points, as the tracker's
  int samples_per_span_;
};

// The pose of a parameter vector (PoseParameters order) in `form`'s canonical member.
ContourPose PoseFromParameters(const Vector6d& parameters, RotationForm form);

}  // namespace hecal::contour
