#include "hecal/uncertainty/unscented.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

#include "hecal/core/error.h"

namespace hecal::uncertainty {

Eigen::MatrixXd CovarianceSquareRoot(const Eigen::MatrixXd& covariance, SquareRoot kind) {
  if (covariance.rows() != covariance.cols()) {
    throw std::invalid_argument("covariance square root: the matrix is not square");
  }
  if (!covariance.allFinite()) {
    throw std::invalid_argument("covariance square root: the matrix is not finite");
  }
  const double scale = covariance.cwiseAbs().maxCoeff();
  if (covariance.rows() == 0 || scale == 0.0) {
    return Eigen::MatrixXd::Zero(covariance.rows(), covariance.cols());
  }
  if ((covariance - covariance.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    throw std::invalid_argument("covariance square root: the matrix is not symmetric");
  }
  const Eigen::MatrixXd symmetric = 0.5 * (covariance + covariance.transpose());
  if (kind == SquareRoot::kCholesky) {
    const Eigen::LLT<Eigen::MatrixXd> llt(symmetric);
    if (llt.info() == Eigen::Success) return llt.matrixL();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(symmetric);
  const Eigen::VectorXd& values = eigen.eigenvalues();
  if (values.minCoeff() < -1e-12 * values.maxCoeff()) {
    throw std::invalid_argument("covariance square root: the matrix is not positive semidefinite");
  }
  const Eigen::VectorXd root = values.cwiseMax(0.0).cwiseSqrt();
  return eigen.eigenvectors() * root.asDiagonal() * eigen.eigenvectors().transpose();
}

std::vector<int> NonZeroColumns(const Eigen::MatrixXd& square_root) {
  std::vector<int> columns;
  for (Eigen::Index i = 0; i < square_root.cols(); ++i) {
    if (square_root.col(i).squaredNorm() > 0.0) columns.push_back(static_cast<int>(i));
  }
  return columns;
}

UnscentedParameters UnscentedParameters::Symmetric(std::optional<double> w0) {
  UnscentedParameters parameters;
  parameters.form = Form::kSymmetric;
  parameters.w0 = w0;
  return parameters;
}

UnscentedParameters UnscentedParameters::Scaled(double alpha, double beta, double kappa) {
  UnscentedParameters parameters;
  parameters.form = Form::kScaled;
  parameters.alpha = alpha;
  parameters.beta = beta;
  parameters.kappa = kappa;
  return parameters;
}

bool UnscentedParameters::IsValid(int n, std::string* why) const {
  std::string problem;
  if (n < 1) {
    problem = "the input dimension must be at least 1";
  } else if (form == Form::kSymmetric) {
    if (w0 && !(std::isfinite(*w0) && *w0 < 1.0)) problem = "w0 must be finite and below 1";
  } else if (!(std::isfinite(alpha) && alpha > 0.0)) {
    problem = "alpha must be positive";
  } else if (!std::isfinite(beta)) {
    problem = "beta must be finite";
  } else if (!(std::isfinite(kappa) && n + kappa > 0.0)) {
    problem = "n + kappa must be positive";
  }
  if (why) *why = problem;
  return problem.empty();
}

SigmaWeights Weights(int n, const UnscentedParameters& parameters) {
  std::string why;
  if (!parameters.IsValid(n, &why)) {
    throw InputError("UnscentedParameters", 0, why,
                     "choose α, β, κ (or w0) that the state dimension allows, e.g. the defaults");
  }
  const double dim = n;
  SigmaWeights w;
  if (parameters.form == UnscentedParameters::Form::kSymmetric) {
    const double w0 = parameters.w0.value_or(1.0 - dim / 3.0);
    w.spread = std::sqrt(dim / (1.0 - w0));
    w.mean_centre = w0;
    w.cov_centre = w0;
    w.other = (1.0 - w0) / (2.0 * dim);
  } else {
    const double alpha2 = parameters.alpha * parameters.alpha;
    const double lambda = alpha2 * (dim + parameters.kappa) - dim;
    w.spread = std::sqrt(dim + lambda);
    w.mean_centre = lambda / (dim + lambda);
    w.cov_centre = w.mean_centre + 1.0 - alpha2 + parameters.beta;
    w.other = 1.0 / (2.0 * (dim + lambda));
  }
  return w;
}

}  // namespace hecal::uncertainty
