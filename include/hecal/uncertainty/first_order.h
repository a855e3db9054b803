// First-order (linear) covariance propagation: Σy = J Σx Jᵀ with J = ∂(f(x̄ ⊞ δ) ⊟ f(x̄))/∂δ at
// δ = 0, and the covariance of a least-squares estimate from its Gauss–Newton information.
//
// Jacobians three ways:
//  - analytic: the caller's J, through Propagate;
//  - automatic: AutoDiffJacobian for a functor templated on its scalar (Eigen's forward-mode
//    AutoDiffScalar: exact derivatives, Eigen only);
//  - numeric, for any f (e.g. a whole solver): FirstOrderTransform differentiates along the
//    columns S_i of the square root of Σx (unscented.h) by central differences,
//        G_i = (f(x̄ ⊞ h S_i) ⊟ f(x̄) − f(x̄ ⊞ −h S_i) ⊟ f(x̄)) / (2h) ≈ J S_i,
//    so Σy = G Gᵀ. The step h is in units of the input's standard deviation along S_i (default
//    1e-3: small enough to be linear, large enough that a solver's convergence tolerance does
//    not swamp the difference). NumericJacobian gives the full J with absolute steps.
// Least squares: for residuals r(θ) whitened to unit covariance with Jacobian J at the optimum,
// Cov(θ̂) ≈ (Jᵀ J)⁻¹ (the inverse Gauss–Newton information; Bard, "Nonlinear parameter
// estimation", 1974, §7). CovarianceFromInformation returns nullopt when the information is
// singular (an unobservable direction) rather than a meaningless inverse.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <stdexcept>
#include <string>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/uncertainty/manifold.h"
#include "hecal/uncertainty/parallel_for.h"
#include "hecal/uncertainty/unscented.h"

namespace hecal::uncertainty {

// J Σ Jᵀ, symmetrised.
Eigen::MatrixXd Propagate(const Eigen::MatrixXd& jacobian, const Eigen::MatrixXd& covariance);

// (information)⁻¹ when the information matrix is symmetric positive definite with its smallest
// eigenvalue above relative_tolerance × its largest; nullopt otherwise.
std::optional<Eigen::MatrixXd> CovarianceFromInformation(const Eigen::MatrixXd& information,
                                                         double relative_tolerance = 1e-12);

// (Jᵀ J)⁻¹ for a whitened residual Jacobian J (rows: residuals, columns: parameters).
std::optional<Eigen::MatrixXd> LeastSquaresCovariance(const Eigen::MatrixXd& whitened_jacobian,
                                                      double relative_tolerance = 1e-12);

// Exact Jacobian of y = f(x) for a functor with
//   template <class T> Eigen::Matrix<T, Eigen::Dynamic, 1> operator()(
//       const Eigen::Matrix<T, Eigen::Dynamic, 1>& x) const;
template <class Functor>
Eigen::MatrixXd AutoDiffJacobian(const Functor& f, const Eigen::VectorXd& x) {
  using Scalar = Eigen::AutoDiffScalar<Eigen::VectorXd>;
  const Eigen::Index n = x.size();
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> xs(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    xs(i) = Scalar(x(i), Eigen::VectorXd::Unit(n, i));
  }
  const Eigen::Matrix<Scalar, Eigen::Dynamic, 1> ys = f(xs);
  Eigen::MatrixXd J(ys.size(), n);
  for (Eigen::Index r = 0; r < ys.size(); ++r) {
    // An output that does not depend on x has an empty derivative vector.
    J.row(r) = ys(r).derivatives().size() == n ? Eigen::RowVectorXd(ys(r).derivatives())
                                               : Eigen::RowVectorXd::Zero(n);
  }
  return J;
}

// Central-difference Jacobian of f(x ⊞ δ) ⊟ f(x) at δ = 0 with absolute step h per coordinate.
template <class In, class Out, class F>
Eigen::MatrixXd NumericJacobian(const F& f, const In& x, double step = 1e-6) {
  using MIn = Manifold<In>;
  using MOut = Manifold<Out>;
  const int n = MIn::Dim(x);
  const Out y0 = f(x);
  Eigen::MatrixXd J(MOut::Dim(y0), n);
  for (int i = 0; i < n; ++i) {
    const Eigen::VectorXd h = step * Eigen::VectorXd::Unit(n, i);
    J.col(i) =
        (MOut::Minus(f(MIn::Plus(x, h)), y0) - MOut::Minus(f(MIn::Plus(x, -h)), y0)) / (2.0 * step);
  }
  return J;
}

struct FirstOrderOptions {
  double step = 1e-3;  // h, in standard deviations along each square-root column
  SquareRoot square_root = SquareRoot::kCholesky;
  int threads = 1;  // f is called concurrently when > 1 (0: every core; at most kMaxThreads)

  // core/options_check.h: false naming FirstOrderOptions.step (not positive and finite) or
  // .threads (outside 0 … kMaxThreads, core/limits.h).
  bool IsValid(std::string* why) const;
};

// Mean f(x̄) and covariance G Gᵀ (above); `evaluations` counts the calls of f. Throws
// hecal::InputError when !options.IsValid, std::invalid_argument for a covariance that is not n ×
// n.
template <class In, class Out, class F>
Moments<Out> FirstOrderTransform(const F& f, const In& mean, const Eigen::MatrixXd& covariance,
                                 const FirstOrderOptions& options = {}) {
  using MIn = Manifold<In>;
  using MOut = Manifold<Out>;
  const int n = MIn::Dim(mean);
  if (covariance.rows() != n || covariance.cols() != n) {
    throw std::invalid_argument("FirstOrderTransform: the covariance is not dim × dim");
  }
  RequireValid(options);
  const Eigen::MatrixXd S = CovarianceSquareRoot(covariance, options.square_root);
  Moments<Out> moments;
  moments.mean = f(mean);
  const std::vector<int> columns = NonZeroColumns(S);
  const int m = MOut::Dim(moments.mean);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(m, n);
  ParallelFor(static_cast<int>(columns.size()), options.threads, [&](int job) {
    const int i = columns[static_cast<size_t>(job)];
    const Eigen::VectorXd h = options.step * S.col(i);
    G.col(i) = (MOut::Minus(f(MIn::Plus(mean, h)), moments.mean) -
                MOut::Minus(f(MIn::Plus(mean, -h)), moments.mean)) /
               (2.0 * options.step);
  });
  moments.covariance = G * G.transpose();
  moments.evaluations = 1 + 2 * static_cast<int>(columns.size());
  return moments;
}

}  // namespace hecal::uncertainty
