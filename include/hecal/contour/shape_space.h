// The shape space of a planar contour (docs/contour.md#shape-space; Blake and Isard, "Active
// Contours", 1998, ch. 4; the contour paper eqs. 1–4): under weak perspective a rigid motion of a
// plane deforms its image by an affinity d' = M d + t, so the control points of the deformed
// contour are
//   Q' = Q0 + W S,    W = ( [1;0], [0;1], [Q0x;0], [0;Q0y], [0;Q0x], [Q0y;0] )     (2N × 6)
// with the shape vector in the paper's order
//   S = (tx, ty, M11 − 1, M22 − 1, M21, M12).
// Q is stacked as (x of every control point, then y of every control point), Blake and Isard's
// layout. S is fitted from observed control points by least squares, S = (WᵀW)⁻¹ Wᵀ (Q' − Q0),
// which is linear in the points, so for independent noise σ on every coordinate its covariance
// is exactly σ² (WᵀW)⁻¹ (FitCovariance).
//
// Reduced shape spaces (the contour paper §II, refs. [2], [3]: when the motion is constrained, S
// lives in a subspace S = B x of dimension k < 6, and fitting x is better conditioned):
//   full               k = 6  any motion
//   similarity         k = 4  (tx, ty, a, b): M = [1+a −b; b 1+a] — the camera translates and
//                             turns about its optical axis in front of a fronto-parallel plane
//                             (M = s·Rot(α) exactly: a = s cos α − 1, b = s sin α)
//   translation-scale  k = 3  (tx, ty, a): M = (1 + a) I — translation only, any direction
//   planar-robot       k = 3  (tx, M11 − 1, M22 − 1) — a camera on a ground robot looking at a
//                             vertical plane: translation along x and z, rotation about the
//                             vertical (image y) axis: M = Z0/(Z0+Tz) diag(cos θ, 1), ty = 0
//   translation        k = 2  (tx, ty): M = I
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string_view>

#include "hecal/geometry/types.h"

namespace hecal::contour {

enum class ShapeSubspace { kFull, kSimilarity, kTranslationScale, kPlanarRobot, kTranslation };

std::optional<ShapeSubspace> ParseShapeSubspace(std::string_view name);
std::string_view ShapeSubspaceName(ShapeSubspace subspace);
// B (6 × k): the full shape vector of reduced coordinates x is S = B x.
Eigen::MatrixXd SubspaceBasis(ShapeSubspace subspace);

// The affinity of a shape vector and back: M = [1 + S2, S5; S4, 1 + S3], t = (S0, S1).
Eigen::Matrix2d AffinityMatrix(const Vector6d& shape);
Eigen::Vector2d AffinityTranslation(const Vector6d& shape);
Vector6d ShapeFromAffinity(const Eigen::Matrix2d& M, const Eigen::Vector2d& t);

class ShapeSpace {
 public:
  // Throws hecal::InputError (source "contour") for fewer than 3 control points or non-finite
  // ones, and hecal::DegenerateError when W B has rank below k: coincident or collinear control
  // points (the affinity is then not observable from the contour).
  explicit ShapeSpace(Eigen::Matrix2Xd template_points,
                      ShapeSubspace subspace = ShapeSubspace::kFull);

  int dim() const { return static_cast<int>(basis_.cols()); }
  ShapeSubspace subspace() const { return subspace_; }
  const Eigen::Matrix2Xd& template_points() const { return template_; }
  const Eigen::MatrixXd& basis() const { return basis_; }  // B, 6 × k
  const Eigen::MatrixXd& W() const { return W_; }          // W B, 2N × k (x rows, then y rows)

  // Least-squares reduced coordinates x of observed control points (2 × N, same order as the
  // template). Throws hecal::InputError when the count differs or a point is not finite.
  Eigen::VectorXd Fit(const Eigen::Matrix2Xd& points) const;
  // σ² (WᵀW)⁻¹: the covariance of Fit for independent noise σ on every coordinate.
  Eigen::MatrixXd FitCovariance(double sigma) const;
  // S = B x, and the control points Q0 + W x.
  Vector6d Shape(const Eigen::VectorXd& x) const;
  Eigen::Matrix2Xd Apply(const Eigen::VectorXd& x) const;
  // The reduced coordinates of a full shape vector (least squares onto the subspace; exact when
  // S is in it).
  Eigen::VectorXd Reduce(const Vector6d& shape) const;

 private:
  Eigen::Matrix2Xd template_;
  ShapeSubspace subspace_;
  Eigen::MatrixXd basis_;
  Eigen::MatrixXd W_;
  Eigen::MatrixXd normal_inverse_;  // (WᵀW)⁻¹
};

}  // namespace hecal::contour
