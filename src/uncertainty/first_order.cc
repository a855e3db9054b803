#include "hecal/uncertainty/first_order.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "hecal/core/limits.h"

namespace hecal::uncertainty {

bool FirstOrderOptions::IsValid(std::string* why) const {
  if (!(step > 0.0) || !std::isfinite(step)) {
    return Invalid(why, "FirstOrderOptions.step", "the step must be positive and finite",
                   "use e.g. 1e-3 (standard deviations)");
  }
  if (!ThreadCountValid(threads, "FirstOrderOptions.threads", why)) return false;
  return true;
}

Eigen::MatrixXd Propagate(const Eigen::MatrixXd& jacobian, const Eigen::MatrixXd& covariance) {
  if (jacobian.cols() != covariance.rows() || covariance.rows() != covariance.cols()) {
    throw std::invalid_argument("Propagate: the Jacobian and covariance sizes do not match");
  }
  const Eigen::MatrixXd result = jacobian * covariance * jacobian.transpose();
  return 0.5 * (result + result.transpose());
}

std::optional<Eigen::MatrixXd> CovarianceFromInformation(const Eigen::MatrixXd& information,
                                                         double relative_tolerance) {
  if (information.rows() != information.cols() || information.rows() == 0 ||
      !information.allFinite()) {
    return std::nullopt;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(
      0.5 * (information + information.transpose()));
  const Eigen::VectorXd& values = eigen.eigenvalues();  // ascending
  if (!(values(0) > relative_tolerance * values(values.size() - 1))) return std::nullopt;
  const Eigen::MatrixXd& V = eigen.eigenvectors();
  return V * values.cwiseInverse().asDiagonal() * V.transpose();
}

std::optional<Eigen::MatrixXd> LeastSquaresCovariance(const Eigen::MatrixXd& whitened_jacobian,
                                                      double relative_tolerance) {
  return CovarianceFromInformation(whitened_jacobian.transpose() * whitened_jacobian,
                                   relative_tolerance);
}

}  // namespace hecal::uncertainty
