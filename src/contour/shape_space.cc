// The shape space of a planar contour: see shape_space.h.
#include "hecal/contour/shape_space.h"

#include <Eigen/Cholesky>
#include <Eigen/SVD>
#include <array>
#include <string>

#include "hecal/core/error.h"
#include "hecal/geometry/dense_decompositions.h"

namespace hecal::contour {
namespace {

struct SubspaceInfo {
  ShapeSubspace subspace;
  std::string_view name;
};
constexpr std::array<SubspaceInfo, 5> kSubspaces = {{
    {ShapeSubspace::kFull, "full"},
    {ShapeSubspace::kSimilarity, "similarity"},
    {ShapeSubspace::kTranslationScale, "translation-scale"},
    {ShapeSubspace::kPlanarRobot, "planar-robot"},
    {ShapeSubspace::kTranslation, "translation"},
}};

// The full W of shape_space.h for control points Q0 (2N × 6).
Eigen::MatrixXd FullW(const Eigen::Matrix2Xd& Q0) {
  const Eigen::Index n = Q0.cols();
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(2 * n, 6);
  W.block(0, 0, n, 1).setOnes();
  W.block(n, 1, n, 1).setOnes();
  W.block(0, 2, n, 1) = Q0.row(0).transpose();
  W.block(n, 3, n, 1) = Q0.row(1).transpose();
  W.block(n, 4, n, 1) = Q0.row(0).transpose();
  W.block(0, 5, n, 1) = Q0.row(1).transpose();
  return W;
}

Eigen::VectorXd Stack(const Eigen::Matrix2Xd& points) {
  Eigen::VectorXd q(2 * points.cols());
  q << points.row(0).transpose(), points.row(1).transpose();
  return q;
}

}  // namespace

std::optional<ShapeSubspace> ParseShapeSubspace(std::string_view name) {
  for (const SubspaceInfo& info : kSubspaces) {
    if (info.name == name) return info.subspace;
  }
  return std::nullopt;
}

std::string_view ShapeSubspaceName(ShapeSubspace subspace) {
  for (const SubspaceInfo& info : kSubspaces) {
    if (info.subspace == subspace) return info.name;
  }
  return "?";
}

Eigen::MatrixXd SubspaceBasis(ShapeSubspace subspace) {
  // Columns in the full order (tx, ty, M11 − 1, M22 − 1, M21, M12).
  switch (subspace) {
    case ShapeSubspace::kFull:
      return Eigen::MatrixXd::Identity(6, 6);
    case ShapeSubspace::kSimilarity: {
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, 4);
      B(0, 0) = B(1, 1) = 1.0;
      B(2, 2) = B(3, 2) = 1.0;  // a: scale
      B(4, 3) = 1.0;            // b: M21 = b
      B(5, 3) = -1.0;           //    M12 = −b
      return B;
    }
    case ShapeSubspace::kTranslationScale: {
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, 3);
      B(0, 0) = B(1, 1) = 1.0;
      B(2, 2) = B(3, 2) = 1.0;
      return B;
    }
    case ShapeSubspace::kPlanarRobot: {
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, 3);
      B(0, 0) = 1.0;
      B(2, 1) = 1.0;
      B(3, 2) = 1.0;
      return B;
    }
    case ShapeSubspace::kTranslation: {
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, 2);
      B(0, 0) = B(1, 1) = 1.0;
      return B;
    }
  }
  return Eigen::MatrixXd::Identity(6, 6);
}

Eigen::Matrix2d AffinityMatrix(const Vector6d& shape) {
  Eigen::Matrix2d M;
  M << 1.0 + shape(2), shape(5), shape(4), 1.0 + shape(3);
  return M;
}

Eigen::Vector2d AffinityTranslation(const Vector6d& shape) {
  return shape.head<2>();
}

Vector6d ShapeFromAffinity(const Eigen::Matrix2d& M, const Eigen::Vector2d& t) {
  Vector6d shape;
  shape << t.x(), t.y(), M(0, 0) - 1.0, M(1, 1) - 1.0, M(1, 0), M(0, 1);
  return shape;
}

ShapeSpace::ShapeSpace(Eigen::Matrix2Xd template_points, ShapeSubspace subspace)
    : template_(std::move(template_points)), subspace_(subspace), basis_(SubspaceBasis(subspace)) {
  if (template_.cols() < 3) {
    throw InputError(
        "contour", 0,
        "the shape space needs at least 3 control points, got " + std::to_string(template_.cols()),
        "give 4 or more control points around the contour");
  }
  if (!template_.allFinite()) {
    throw InputError("contour", 0, "a template control point is not finite",
                     "give finite x, y for every control point");
  }
  W_ = FullW(template_) * basis_;
  // Rank test on unit-norm columns, so that the threshold does not depend on the contour's
  // size.
  Eigen::MatrixXd scaled = W_;
  for (Eigen::Index c = 0; c < scaled.cols(); ++c) {
    const double norm = scaled.col(c).norm();
    if (norm > 0.0) scaled.col(c) /= norm;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled);
  const Eigen::VectorXd& sv = svd.singularValues();
  if (!(sv.minCoeff() > 1e-9 * sv.maxCoeff())) {
    throw DegenerateError(
        "the affine deformation of this contour: its control points are coincident or collinear, "
        "so W has rank below " +
            std::to_string(dim()) + " (" + std::string(ShapeSubspaceName(subspace)) +
            " shape space)",
        "use a contour whose control points span an area (a closed outline, not a line)");
  }
  normal_inverse_ = (W_.transpose() * W_).ldlt().solve(Eigen::MatrixXd::Identity(dim(), dim()));
}

Eigen::VectorXd ShapeSpace::Fit(const Eigen::Matrix2Xd& points) const {
  if (points.cols() != template_.cols()) {
    throw InputError("contour", 0,
                     "expected " + std::to_string(template_.cols()) + " control points, got " +
                         std::to_string(points.cols()),
                     "give the deformed contour with the template's control points, in order");
  }
  if (!points.allFinite()) {
    throw InputError("contour", 0, "a control point is not finite",
                     "give finite x, y for every control point");
  }
  return normal_inverse_ * (W_.transpose() * (Stack(points) - Stack(template_)));
}

Eigen::MatrixXd ShapeSpace::FitCovariance(double sigma) const {
  return sigma * sigma * normal_inverse_;
}

Vector6d ShapeSpace::Shape(const Eigen::VectorXd& x) const {
  return basis_ * x;
}

Eigen::Matrix2Xd ShapeSpace::Apply(const Eigen::VectorXd& x) const {
  const Eigen::VectorXd q = Stack(template_) + W_ * x;
  const Eigen::Index n = template_.cols();
  Eigen::Matrix2Xd points(2, n);
  points.row(0) = q.head(n).transpose();
  points.row(1) = q.tail(n).transpose();
  return points;
}

Eigen::VectorXd ShapeSpace::Reduce(const Vector6d& shape) const {
  return basis_.colPivHouseholderQr().solve(shape);
}

}  // namespace hecal::contour
