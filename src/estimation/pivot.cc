#include "hecal/estimation/pivot.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/dense_decompositions.h"
#include "hecal/geometry/skew.h"
#include "hecal/handeye/observability.h"

namespace hecal::estimation {
namespace {

constexpr double kChiSquare3Median = 2.365974;  // χ²₃(0.5)

using Vector6 = Vector6d;

std::string Direction(const Eigen::Vector3d& v) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.3f, %.3f, %.3f)", v.x(), v.y(), v.z());
  return text;
}

// (P3) for the sigma `sigma`.
Eigen::Matrix3d ResidualCovariance(const Eigen::Matrix3d& R, const Eigen::Vector3d& tip,
                                   const PoseSigma& sigma) {
  const Eigen::Matrix3d lever = R * Skew(tip);
  return sigma.translation * sigma.translation * Eigen::Matrix3d::Identity() +
         sigma.rotation * sigma.rotation * lever * lever.transpose();
}

Eigen::Vector3d Residual(const Pose& T, const Vector6& x) {
  return T.linear() * x.head<3>() + T.translation() - x.tail<3>();
}

// (P2) over the stations in `used`.
Vector6 AlgebraicFit(const std::vector<Pose>& poses, const std::vector<int>& used) {
  Eigen::MatrixXd A(3 * used.size(), 6);
  Eigen::VectorXd b(3 * used.size());
  for (size_t k = 0; k < used.size(); ++k) {
    const Pose& T = poses[used[k]];
    A.block<3, 3>(3 * k, 0) = T.linear();
    A.block<3, 3>(3 * k, 3) = -Eigen::Matrix3d::Identity();
    b.segment<3>(3 * k) = -T.translation();
  }
  return ColPivQrSolve(A, b);
}

struct Fit {
  Vector6 x = Vector6::Zero();
  Matrix6d information = Matrix6d::Zero();  // Σ J_iᵀ C_i⁻¹ J_i at `shape`
  double chi_square = 0.0;                  // at `shape`
  int iterations = 0;
};

// (P4) from `start`, weights at the sigma `shape`.
Fit GeneralisedFit(const std::vector<Pose>& poses, const std::vector<int>& used,
                   const Vector6& start, const PoseSigma& shape) {
  Fit fit;
  fit.x = start;
  for (fit.iterations = 1; fit.iterations <= kPivotIterations; ++fit.iterations) {
    Matrix6d N = Matrix6d::Zero();
    Vector6 rhs = Vector6::Zero();
    for (int i : used) {
      const Eigen::Matrix3d& R = poses[i].linear();
      const Eigen::Matrix3d W = ResidualCovariance(R, fit.x.head<3>(), shape).inverse();
      Eigen::Matrix<double, 3, 6> J;
      J << R, -Eigen::Matrix3d::Identity();
      N += J.transpose() * W * J;
      rhs -= J.transpose() * W * poses[i].translation();
    }
    const Vector6 next = N.ldlt().solve(rhs);
    const double step = (next - fit.x).norm();
    fit.x = next;
    if (step < 1e-12) break;
  }
  fit.iterations = std::min(fit.iterations, kPivotIterations);
  fit.information.setZero();
  fit.chi_square = 0.0;
  for (int i : used) {
    const Eigen::Matrix3d& R = poses[i].linear();
    const Eigen::Matrix3d W = ResidualCovariance(R, fit.x.head<3>(), shape).inverse();
    Eigen::Matrix<double, 3, 6> J;
    J << R, -Eigen::Matrix3d::Identity();
    fit.information += J.transpose() * W * J;
    const Eigen::Vector3d e = Residual(poses[i], fit.x);
    fit.chi_square += e.dot(W * e);
  }
  return fit;
}

double SquaredStandardized(const Pose& T, const Vector6& x, const PoseSigma& sigma) {
  const Eigen::Vector3d e = Residual(T, x);
  return e.dot(ResidualCovariance(T.linear(), x.head<3>(), sigma).ldlt().solve(e));
}

PoseSigma Scaled(const PoseSigma& shape, double k) {
  return {shape.rotation * k, shape.translation * k};
}

// Step 6 on the rotations: returns sqrt(λ₃) and its eigenvector (flange frame) and R̄ v₃.
struct Spread {
  double max_tilt = 0.0;
  double min_tilt = 0.0;
  Eigen::Vector3d flange_axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d base_axis = Eigen::Vector3d::UnitZ();
};

Spread RotationSpread(const std::vector<Pose>& poses) {
  Eigen::Matrix3d mean = Eigen::Matrix3d::Zero();
  for (const Pose& T : poses) mean += T.linear();
  mean /= static_cast<double>(poses.size());
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  for (const Pose& T : poses) {
    const Eigen::Matrix3d D = T.linear() - mean;
    S += D.transpose() * D;
  }
  S /= static_cast<double>(poses.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(S);  // ascending
  Spread spread;
  spread.min_tilt = std::sqrt(std::max(eigen.eigenvalues()(0), 0.0));
  spread.max_tilt = std::sqrt(std::max(eigen.eigenvalues()(2), 0.0));
  spread.flange_axis = eigen.eigenvectors().col(0);
  const Eigen::Vector3d base = mean * spread.flange_axis;
  spread.base_axis = base.norm() > 1e-9
                         ? Eigen::Vector3d(base.normalized())
                         : Eigen::Vector3d(poses.front().linear() * spread.flange_axis);
  return spread;
}

[[noreturn]] void ThrowOneAxis(const Spread& spread, const std::string& why) {
  throw DegenerateError(
      "the tip offset along the flange axis " + Direction(spread.flange_axis) +
          " and the pivot point along the base axis " + Direction(spread.base_axis) + " (" + why +
          ")",
      "tilt the tool about a second axis as well, by 10 to 30 degrees either way");
}

void CheckRotationSpread(const Spread& spread) {
  char tilt[96];
  if (spread.max_tilt < kPivotMinTilt) {
    std::snprintf(tilt, sizeof tilt, "the orientations differ by %.2f deg RMS, below %.0f deg",
                  spread.max_tilt * kDegreesPerRadian, kPivotMinTilt * kDegreesPerRadian);
    throw DegenerateError(std::string("the tip offset or the pivot point (the tool barely "
                                      "rotated: ") +
                              tilt + ")",
                          "tilt the tool about two axes by 10 to 30 degrees either way around "
                          "the pivot");
  }
  if (spread.min_tilt < kPivotMinTilt) {
    std::snprintf(tilt, sizeof tilt,
                  "the tool rotated about that axis only: %.2f deg RMS about the others, below "
                  "%.0f deg",
                  spread.min_tilt * kDegreesPerRadian, kPivotMinTilt * kDegreesPerRadian);
    ThrowOneAxis(spread, tilt);
  }
}

}  // namespace

bool PivotOptions::IsValid(std::string* why) const {
  if (!SigmaIsValid(sigma, "PivotOptions.sigma", why)) return false;
  if (sigma && sigma->translation <= 0.0) {
    return Invalid(why, "PivotOptions.sigma",
                   "the translation noise must be above 0 (it weighs the residuals)",
                   "give the robot's translation noise per axis, e.g. 0.05 mm, or leave the "
                   "noise out to estimate it");
  }
  return true;
}

PivotResult CalibratePivot(const std::vector<Pose>& T_base_flange, const PivotOptions& options) {
  RequireValid(options);
  const int n = static_cast<int>(T_base_flange.size());
  if (n < 3) {
    throw DegenerateError(
        "the tip offset and the pivot point from " + std::to_string(n) + " station(s)",
        "record at least 3 orientations (10 or more, tilted about two axes)");
  }
  const Spread spread = RotationSpread(T_base_flange);
  CheckRotationSpread(spread);

  PivotResult result;
  result.min_tilt = spread.min_tilt;
  result.sigma_estimated = !options.sigma.has_value();
  const PoseSigma shape = options.sigma.value_or(kPivotNoiseShape);
  std::vector<int> all(n);
  for (int i = 0; i < n; ++i) all[i] = i;
  const Vector6 start = AlgebraicFit(T_base_flange, all);
  result.algebraic_tip = start.head<3>();
  result.algebraic_pivot = start.tail<3>();

  std::vector<int> used = all;
  std::vector<bool> flagged(n, false);
  std::vector<std::string> rejection_warnings;
  Fit fit;
  for (int round = 0; round < kPivotRejectionRounds; ++round) {
    fit = GeneralisedFit(T_base_flange, used, round == 0 ? start : fit.x, shape);
    // The flag scale from the median of the used stations (step 5).
    std::vector<double> chi(n);
    for (int i = 0; i < n; ++i) chi[i] = SquaredStandardized(T_base_flange[i], fit.x, shape);
    std::vector<double> inliers;
    for (int i : used) inliers.push_back(chi[i]);
    std::nth_element(inliers.begin(), inliers.begin() + inliers.size() / 2, inliers.end());
    const double median2 = inliers[inliers.size() / 2] / kChiSquare3Median;
    const double scale2 =
        result.sigma_estimated ? std::max(median2, 1e-12) : std::max(median2, 1.0);
    std::vector<int> kept;
    for (int i = 0; i < n; ++i) {
      flagged[i] = chi[i] / scale2 > kPivotOutlierChiSquare;
      if (!flagged[i]) kept.push_back(i);
    }
    if (!options.reject_outliers || kept == used) break;
    const int minimum = std::max(4, (n + 1) / 2);
    if (static_cast<int>(kept.size()) < minimum) {
      rejection_warnings.push_back(std::to_string(n - static_cast<int>(kept.size())) + " of " +
                                   std::to_string(n) +
                                   " stations flagged as outliers: too many to leave out, every "
                                   "station kept (check the pivot was held fixed)");
      if (used != all) fit = GeneralisedFit(T_base_flange, all, fit.x, shape);
      used = all;
      break;
    }
    used = kept;
    if (round + 1 == kPivotRejectionRounds) fit = GeneralisedFit(T_base_flange, used, fit.x, shape);
  }

  const int m = static_cast<int>(used.size());
  result.dof = 3 * m - 6;
  const double k = result.sigma_estimated ? std::sqrt(fit.chi_square / result.dof) : 1.0;
  result.sigma = Scaled(shape, k);
  result.tip = fit.x.head<3>();
  result.pivot = fit.x.tail<3>();
  result.iterations = fit.iterations;
  result.chi_square = fit.chi_square / (k * k > 0.0 ? k * k : 1.0);
  result.covariance = (k * k) * fit.information.inverse();
  result.covariance = 0.5 * (result.covariance + result.covariance.transpose()).eval();
  double sum = 0.0;
  result.stations.resize(n);
  for (int i = 0; i < n; ++i) {
    PivotStation& station = result.stations[i];
    station.residual = Residual(T_base_flange[i], fit.x);
    station.used = std::find(used.begin(), used.end(), i) != used.end();
    station.outlier = flagged[i];
    station.standardized =
        k > 0.0 ? std::sqrt(SquaredStandardized(T_base_flange[i], fit.x, result.sigma)) : 0.0;
    if (station.used) sum += station.residual.squaredNorm();
  }
  result.rms = std::sqrt(sum / m);

  if (result.sigma.rotation > 0.0) {
    const double rho =
        spread.min_tilt * spread.min_tilt / (2.0 * result.sigma.rotation * result.sigma.rotation);
    if (rho < handeye::kNoiseDegenerate) {
      char why[128];
      std::snprintf(why, sizeof why,
                    "the tilt about the other axes, %.3f deg RMS, is within the rotation noise "
                    "%.3f deg",
                    spread.min_tilt * kDegreesPerRadian, result.sigma.rotation * kDegreesPerRadian);
      ThrowOneAxis(spread, why);
    }
  }
  if (result.sigma_estimated) {
    char note[160];
    std::snprintf(note, sizeof note,
                  "noise not given (--robot-sigma): estimated as %.4g mm / %.4g deg per axis "
                  "(one scale on 1 mm : 1 deg, from chi-square / %d dof)",
                  result.sigma.translation * 1e3, result.sigma.rotation * kDegreesPerRadian,
                  result.dof);
    result.warnings.push_back(note);
  }
  for (std::string& warning : rejection_warnings) result.warnings.push_back(std::move(warning));
  return result;
}

}  // namespace hecal::estimation
