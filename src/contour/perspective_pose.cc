// The camera motion of a contour without weak perspective's bias: see perspective_pose.h.
#include "hecal/contour/perspective_pose.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <optional>

#include "hecal/contour/bspline.h"
#include "hecal/contour/perspective_view.h"
#include "hecal/contour/pose_uncertainty.h"
#include "hecal/core/error.h"
#include "hecal/geometry/euler.h"
#include "hecal/geometry/so3.h"

namespace hecal::contour {
namespace {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

ContourPose PoseFromParameters(const Vector6d& parameters, RotationForm form) {
  // PoseParameters holds (Rx, Ry, Rz) for zyx, the reverse of the sequence's (Rz, Ry, Rx).
  const Eigen::Vector3d euler = form == RotationForm::kZyx
                                    ? Eigen::Vector3d(parameters.tail<3>().reverse())
                                    : Eigen::Vector3d(parameters.tail<3>());
  return CanonicalPose(MatrixFromEuler(euler, *EulerSequence::Parse(RotationSequence(form))),
                       parameters.head<3>(), form);
}

PerspectivePoseModel::PerspectivePoseModel(const Eigen::Matrix2Xd& template_points,
                                           const ContourCamera& camera, int samples_per_span)
    : camera_(camera),
      target_(template_points * (camera.z0 / camera.focal)),
      space_(template_points),
      samples_per_span_(std::max(1, samples_per_span)) {
  ValidateContourCamera(camera_);
}

Vector6d PerspectivePoseModel::PerspectiveShape(const Eigen::Matrix3d& rotation,
                                                const Eigen::Vector3d& translation) const {
  // Start: the least-squares fit of the projected control points.
  Eigen::VectorXd x =
      space_.Fit(ProjectPerspective(target_.control_points(), rotation, translation, camera_));
  // Then the tracker's fit: the normal distances from the affine curve's samples to the true
  // outline q(u) = f (X(u), Y(u)) / Z(u), X(u) = R (p(u), 0) + (Tx, Ty, Z0 + Tz), p the target's
  // curve. Each normal meets the outline at u with (q(u) − r) × n = 0 (Newton in u from the same
  // parameter; the outline is a small deformation of the curve).
  const Eigen::Vector3d offset(translation.x(), translation.y(), camera_.z0 + translation.z());
  const auto project = [&](double u, Eigen::Vector2d* q, Eigen::Vector2d* dq) {
    const Eigen::Vector3d X = rotation.leftCols<2>() * target_.Point(u) + offset;
    const Eigen::Vector3d dX = rotation.leftCols<2>() * target_.Tangent(u);
    *q = camera_.focal * X.head<2>() / X.z();
    *dq = camera_.focal * (dX.head<2>() / X.z() - X.head<2>() * dX.z() / (X.z() * X.z()));
  };
  const Eigen::Index n = space_.template_points().cols();
  const Eigen::VectorXd s = target_.SampleParameters(samples_per_span_);
  for (int iteration = 0; iteration < 6; ++iteration) {
    const ClosedBSpline curve(space_.Apply(x));
    Eigen::MatrixXd H(s.size(), space_.dim());
    Eigen::VectorXd d(s.size());
    for (Eigen::Index j = 0; j < s.size(); ++j) {
      const Eigen::Vector2d r = curve.Point(s(j)), normal = curve.Normal(s(j));
      double u = s(j);
      Eigen::Vector2d q, dq;
      for (int k = 0; k < 4; ++k) {
        project(u, &q, &dq);
        const double slope = Cross(dq, normal);
        if (slope == 0.0) break;
        u -= Cross(q - r, normal) / slope;
      }
      project(u, &q, &dq);
      const Eigen::RowVectorXd basis = curve.Basis(s(j));
      H.row(j) = normal.x() * (basis * space_.W().topRows(n)) +
                 normal.y() * (basis * space_.W().bottomRows(n));
      d(j) = normal.dot(q - r);
    }
    const Eigen::VectorXd step = (H.transpose() * H).ldlt().solve(H.transpose() * d);
    x += step;
    if (step.cwiseAbs().maxCoeff() < 1e-13 * (1.0 + x.cwiseAbs().maxCoeff())) break;
  }
  return space_.Shape(x);
}

std::optional<ContourPose> PerspectivePoseModel::Newton(const Vector6d& shape, Eigen::Matrix3d R,
                                                        Eigen::Vector3d T, RotationForm form,
                                                        int max_iterations) const {
  // Newton on A(R, T) = S with R = R_k Exp(ω) (right perturbation) and T additive; the Jacobian by
  // central differences (A is smooth, 12 cheap evaluations).
  const double tolerance_t = 1e-10 * camera_.focal;
  constexpr double kToleranceM = 1e-12;
  const double h_t = 1e-6 * camera_.z0;
  constexpr double kAngleStep = 1e-7;
  for (int k = 0; k <= max_iterations; ++k) {
    const Vector6d residual = PerspectiveShape(R, T) - shape;
    if (!residual.allFinite()) return std::nullopt;
    if (residual.head<2>().cwiseAbs().maxCoeff() <= tolerance_t &&
        residual.tail<4>().cwiseAbs().maxCoeff() <= kToleranceM) {
      ContourPose pose = CanonicalPose(R, T, form);
      if ((pose.rotation - R).norm() > 1e-9) {  // Newton's branch is the other member (header)
        pose.rotation = R;
        pose.euler = EulerAngles(R, form);
      }
      return pose;
    }
    Matrix6d J;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d w = kAngleStep * Eigen::Vector3d::Unit(j);
      J.col(j) = (PerspectiveShape(R * so3::Exp(w), T) - PerspectiveShape(R * so3::Exp(-w), T)) /
                 (2 * kAngleStep);
      const Eigen::Vector3d dt = h_t * Eigen::Vector3d::Unit(j);
      J.col(3 + j) = (PerspectiveShape(R, T + dt) - PerspectiveShape(R, T - dt)) / (2 * h_t);
    }
    const Eigen::FullPivLU<Matrix6d> lu(J);
    if (!lu.isInvertible()) return std::nullopt;
    const Vector6d step = -lu.solve(residual);
    const Eigen::Vector3d w = step.head<3>();
    R = R * so3::Exp(w);
    T += step.tail<3>();
  }
  return std::nullopt;
}

namespace {

bool IsCanonical(const ContourPose& pose) {
  return (CanonicalPose(pose.rotation, pose.translation, pose.form).rotation - pose.rotation)
             .norm() <= 1e-9;
}

}  // namespace

ContourPose PerspectivePoseModel::Pose(const Vector6d& shape, RotationForm form,
                                       int max_iterations) const {
  // Both Necker members have a root (header); start from the weak pose, and from its mirror when
  // the first root is not the form's member.
  const ContourPose weak = PoseFromShape(shape, camera_, form);
  std::optional<ContourPose> pose =
      Newton(shape, weak.rotation, weak.translation, form, max_iterations);
  if (!pose || !IsCanonical(*pose)) {
    std::optional<ContourPose> other =
        Newton(shape, NeckerMirror(weak.rotation), weak.translation, form, max_iterations);
    if (other && (!pose || IsCanonical(*other))) pose = other;
  }
  if (pose) return *pose;
  throw DegenerateError(
      "the perspective pose: Newton's method did not converge on the perspective image (the "
      "target near edge-on or close to the camera)",
      "use the weak-perspective pose (--pose-model weak)");
}

}  // namespace hecal::contour
