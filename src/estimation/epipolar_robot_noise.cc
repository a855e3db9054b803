#include "hecal/estimation/epipolar_robot_noise.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <string>

#include "epipolar_jacobians.h"
#include "epipolar_residual.h"
#include "hecal/core/error.h"

namespace hecal::estimation {
namespace {

// The model linearised at X, reduced to the products the likelihood and the GLS step need.
struct Linearisation {
  int n = 0;  // pairs
  double rr = 0.0;
  Matrix6d JJ = Matrix6d::Zero();
  Vector6d Jr = Vector6d::Zero();
  Eigen::MatrixXd GG, GJ;  // p × p, p × 6
  Eigen::VectorXd Gr;      // p
};

Linearisation Linearise(const global::EpipolarProblem& problem, const Pose& X) {
  const detail::EpipolarJacobians d = detail::DifferentiateEpipolar(problem, X);
  const Eigen::MatrixXd& G = d.G;
  const Eigen::MatrixXd& J = d.J;
  const Eigen::VectorXd& r = d.r;
  Linearisation lin;
  lin.n = int(r.size());
  lin.rr = r.squaredNorm();
  lin.JJ = J.transpose() * J;
  lin.Jr = J.transpose() * r;
  lin.GG = G.transpose() * G;
  lin.GJ = G.transpose() * J;
  lin.Gr = G.transpose() * r;
  return lin;
}

// Jᵀ V⁻¹ J, Jᵀ V⁻¹ r̂, r̂ᵀ V⁻¹ r̂ and log det V for the noise (Woodbury, header comment).
struct Weighted {
  Matrix6d JVJ;
  Vector6d JVr;
  double rVr = 0.0;
  double log_det_V = 0.0;
};

Weighted Weigh(const Linearisation& lin, const EpipolarNoise& noise) {
  const int p = int(lin.GG.rows());
  Eigen::VectorXd d(p);  // D^½
  for (int k = 0; k < p; ++k) {
    d[k] = k % 6 < 3 ? noise.robot_rotation_sigma : noise.robot_translation_sigma;
  }
  const double s2 = noise.ray_sigma * noise.ray_sigma;
  const Eigen::MatrixXd K =
      Eigen::MatrixXd::Identity(p, p) + d.asDiagonal() * lin.GG * d.asDiagonal() / s2;
  const Eigen::LLT<Eigen::MatrixXd> llt(K);
  const Eigen::MatrixXd F = d.asDiagonal() * lin.GJ;
  const Eigen::VectorXd f = d.asDiagonal() * lin.Gr;
  const Eigen::MatrixXd KF = llt.solve(F);
  const Eigen::VectorXd Kf = llt.solve(f);
  Weighted w;
  w.JVJ = lin.JJ / s2 - F.transpose() * KF / (s2 * s2);
  w.JVr = lin.Jr / s2 - F.transpose() * Kf / (s2 * s2);
  w.rVr = lin.rr / s2 - f.dot(Kf) / (s2 * s2);
  const Eigen::MatrixXd L = llt.matrixL();
  w.log_det_V = lin.n * std::log(s2) + 2.0 * L.diagonal().array().log().sum();
  return w;
}

double RestrictedLogLikelihood(const Linearisation& lin, const EpipolarNoise& noise) {
  const Weighted w = Weigh(lin, noise);
  const Eigen::LLT<Matrix6d> llt(w.JVJ);
  const Matrix6d L = llt.matrixL();
  const double log_det_JVJ = 2.0 * L.diagonal().array().log().sum();
  return -0.5 * (w.log_det_V + log_det_JVJ + w.rVr - w.JVr.dot(llt.solve(w.JVr)));
}

}  // namespace

EpipolarNoise EstimateEpipolarNoise(const global::EpipolarProblem& problem, const Pose& X,
                                    const std::optional<PoseSigma>& robot) {
  const Linearisation lin = Linearise(problem, X);
  // Log-variances, searched within wide bounds round the plain residual variance s0².
  const double s0 = std::max(1e-300, lin.rr / std::max(1, lin.n - 6));
  double log_var[3] = {std::log(s0), std::log(s0) - 12.0, std::log(s0) - 12.0};
  if (robot) {  // held: a zero σ is a log-variance of −∞, which noise_of maps back to 0
    log_var[1] = 2.0 * std::log(robot->rotation);
    log_var[2] = 2.0 * std::log(robot->translation);
  }
  const int searched = robot ? 1 : 3;
  const double low[3] = {std::log(s0) - 16.0, std::log(s0) - 30.0, std::log(s0) - 30.0};
  const double high[3] = {std::log(s0) + 1.0, std::log(s0) + 8.0, std::log(s0) + 8.0};
  const auto noise_of = [](const double* v) {
    return EpipolarNoise{std::exp(0.5 * v[0]), std::exp(0.5 * v[1]), std::exp(0.5 * v[2])};
  };
  const auto value = [&](int k, double x) {
    double v[3] = {log_var[0], log_var[1], log_var[2]};
    v[k] = x;
    const double l = RestrictedLogLikelihood(lin, noise_of(v));
    return std::isfinite(l) ? l : -1e300;
  };
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int sweep = 0; sweep < 8; ++sweep) {
    double largest_change = 0.0;
    for (int k = 0; k < searched; ++k) {
      double a = low[k], b = high[k];
      double c = b - golden * (b - a), d = a + golden * (b - a);
      double fc = value(k, c), fd = value(k, d);
      while (b - a > 1e-3) {
        if (fc > fd) {
          b = d, d = c, fd = fc;
          c = b - golden * (b - a);
          fc = value(k, c);
        } else {
          a = c, c = d, fc = fd;
          d = a + golden * (b - a);
          fd = value(k, d);
        }
      }
      largest_change = std::max(largest_change, std::abs(0.5 * (a + b) - log_var[k]));
      log_var[k] = 0.5 * (a + b);
    }
    if (largest_change < 0.01) break;  // 0.5% in σ
  }
  EpipolarNoise noise = noise_of(log_var);
  if (robot) {  // exactly as given
    noise.robot_rotation_sigma = robot->rotation;
    noise.robot_translation_sigma = robot->translation;
  }
  return noise;
}

EpipolarPolish PolishWithRobotNoise(const global::EpipolarProblem& problem, const Pose& start,
                                    const EpipolarNoise& noise) {
  Pose X = start;
  Weighted w;
  Linearisation lin;
  for (int iteration = 0; iteration < 20; ++iteration) {
    lin = Linearise(problem, X);
    w = Weigh(lin, noise);
    const Vector6d delta = -w.JVJ.ldlt().solve(w.JVr);
    if (!delta.allFinite()) break;
    X = detail::ApplyDelta(X, delta.data());
    if (delta.norm() < 1e-12) break;
  }
  lin = Linearise(problem, X);
  w = Weigh(lin, noise);
  EpipolarPolish polish;
  polish.X = X;
  polish.pairs = lin.n;
  polish.rms = std::sqrt(lin.rr / lin.n);
  polish.ray_sigma = noise.ray_sigma;
  polish.covariance = w.JVJ.inverse();
  return polish;
}

PoseSigma HandPoseSigma(handeye::Setup setup, const PoseSigma& robot,
                        double mean_squared_distance) {
  if (setup == handeye::Setup::kEyeInHand) return robot;
  return {robot.rotation,
          std::sqrt(robot.translation * robot.translation +
                    2.0 / 3.0 * robot.rotation * robot.rotation * mean_squared_distance)};
}

RobotNoisePolish PolishWithEstimatedRobotNoise(const global::EpipolarProblem& problem,
                                               const Pose& start, double reach,
                                               const std::optional<PoseSigma>& robot) {
  RobotNoisePolish result;
  result.stations = int(detail::EpipolarStationIndex(problem).size());
  result.robot_given = robot.has_value();
  result.noise = EstimateEpipolarNoise(problem, start, robot);
  result.polish = PolishWithRobotNoise(problem, start, result.noise);
  result.noise = EstimateEpipolarNoise(problem, result.polish.X, robot);
  result.polish = PolishWithRobotNoise(problem, result.polish.X, result.noise);
  const EpipolarPolish& p = result.polish;
  if (!p.X.matrix().allFinite() || !p.covariance.allFinite() ||
      p.covariance.llt().info() != Eigen::Success || !(p.X.translation().norm() <= reach)) {
    throw DegenerateError(
        "the length of X's translation from these motions (the polish drifts without limit: "
        "motions that rotate the hand about its own origin observe only its direction)",
        "add motions in which the robot also translates, by a few centimetres or more");
  }
  return result;
}

EpipolarJackknife ExpectedEpipolarJackknife(const global::EpipolarProblem& problem, const Pose& X,
                                            const EpipolarNoise& noise,
                                            const std::vector<std::vector<bool>>& kept) {
  const detail::EpipolarJacobians d = detail::DifferentiateEpipolar(problem, X);
  const int n = int(d.r.size());
  const int p = int(d.G.cols());
  const int groups = int(kept.size());
  Eigen::VectorXd D(p);  // the nuisances' variances
  for (int k = 0; k < p; ++k) {
    const double s = k % 6 < 3 ? noise.robot_rotation_sigma : noise.robot_translation_sigma;
    D[k] = s * s;
  }
  const double s2 = noise.ray_sigma * noise.ray_sigma;
  const auto apply_V = [&](const Eigen::MatrixXd& Y) {  // V Y, Y n × k
    return Eigen::MatrixXd(s2 * Y + d.G * (D.asDiagonal() * (d.G.transpose() * Y)));
  };
  // M on the pairs with rows[i] (zero elsewhere), 6 × n: V_S⁻¹ by Woodbury in the nuisances.
  const auto estimator = [&](const std::vector<bool>& rows) {
    Eigen::MatrixXd GS = d.G, JS = d.J;
    for (int i = 0; i < n; ++i) {
      if (!rows[std::size_t(i)]) GS.row(i).setZero(), JS.row(i).setZero();
    }
    const Eigen::VectorXd root = D.cwiseSqrt();
    const Eigen::MatrixXd F = GS * root.asDiagonal();  // n × p
    const Eigen::MatrixXd K = Eigen::MatrixXd::Identity(p, p) + F.transpose() * F / s2;
    const Eigen::MatrixXd W =
        (JS - F * Eigen::LLT<Eigen::MatrixXd>(K).solve(F.transpose() * JS) / s2) / s2;  // V_S⁻¹ J_S
    const Matrix6d C = (JS.transpose() * W).inverse();
    return Eigen::MatrixXd(C * W.transpose());
  };
  std::vector<int> motion_of;  // per pair
  for (int m = 0; m < int(problem.motions.size()); ++m) {
    motion_of.insert(motion_of.end(), problem.motions[std::size_t(m)].pairs.size(), m);
  }
  const Eigen::MatrixXd M = estimator(std::vector<bool>(std::size_t(n), true));
  std::vector<Eigen::MatrixXd> L;
  Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(6, n);
  for (const std::vector<bool>& motions : kept) {
    std::vector<bool> rows(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      rows[std::size_t(i)] = motions[std::size_t(motion_of[std::size_t(i)])];
    L.push_back(estimator(rows) - M);
    mean += L.back() / groups;
  }
  EpipolarJackknife out;
  const double factor = (groups - 1.0) / groups;
  for (Eigen::MatrixXd& l : L) {
    l -= mean;
    out.covariance += factor * l * apply_V(l.transpose());
  }
  for (int k = 0; k < 6; ++k) {
    Eigen::MatrixXd A(groups, n);
    for (int g = 0; g < groups; ++g) A.row(g) = L[std::size_t(g)].row(k);
    const Eigen::MatrixXd S = A * apply_V(A.transpose());
    const double trace = S.trace();
    out.relative_error[k] = trace > 0.0 ? std::sqrt(2.0 * S.squaredNorm()) / trace : 0.0;
  }
  return out;
}

}  // namespace hecal::estimation
