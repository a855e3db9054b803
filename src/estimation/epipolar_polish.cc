#include "hecal/estimation/epipolar_polish.h"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <algorithm>
#include <cmath>

#include "hecal/core/error.h"

namespace hecal::estimation {
namespace {

template <typename T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

template <typename T>
T Sampson(const Vec3<T>& v, const Vec3<T>& Ru, const Vec3<T>& t_A, const Vec3<T>& u,
          const Eigen::Matrix<T, 3, 3>& R_A) {
  const Vec3<T> g_v = Ru.cross(t_A);
  const Vec3<T> g_u = R_A.transpose() * t_A.cross(v);
  const Vec3<T> p_v = g_v - v * v.dot(g_v);
  const Vec3<T> p_u = g_u - u * u.dot(g_u);
  const T scale = sqrt(p_v.squaredNorm() + p_u.squaredNorm() + T(1e-300));
  return v.dot(g_v) / scale;
}

// Residual of one pair as a function of δ = (ω, τ): R = R̂ Exp(ω), t = t̂ + R̂ τ.
struct PairCost {
  PairCost(const Pose& X0, const Pose& B, const global::BearingPair& pair)
      : X0_(X0), B_(B), pair_(pair) {}

  template <typename T>
  bool operator()(const T* delta, T* residual) const {
    Eigen::Matrix<T, 3, 3> E;
    ceres::AngleAxisToRotationMatrix(delta, ceres::ColumnMajorAdapter3x3(E.data()));
    const Eigen::Matrix<T, 3, 3> R = X0_.linear().cast<T>() * E;
    const Vec3<T> tau(delta[3], delta[4], delta[5]);
    const Vec3<T> t = X0_.translation().cast<T>() + X0_.linear().cast<T>() * tau;
    const Eigen::Matrix<T, 3, 3> R_B = B_.linear().cast<T>();
    const Eigen::Matrix<T, 3, 3> R_A = R.transpose() * R_B * R;
    const Vec3<T> t_A = R.transpose() * (R_B * t + B_.translation().cast<T>() - t);
    const Vec3<T> u = pair_.second.normalized().cast<T>();
    residual[0] = Sampson<T>(pair_.first.normalized().cast<T>(), R_A * u, t_A, u, R_A);
    return true;
  }

  Pose X0_, B_;
  global::BearingPair pair_;
};

Pose Apply(const Pose& X0, const double* delta) {
  Eigen::Matrix3d E;
  ceres::AngleAxisToRotationMatrix(delta, ceres::ColumnMajorAdapter3x3(E.data()));
  return MakePose(X0.linear() * E,
                  X0.translation() + X0.linear() * Eigen::Vector3d(delta[3], delta[4], delta[5]));
}

}  // namespace

double SampsonAngle(const Pose& X, const Pose& hand_motion, const global::BearingPair& pair) {
  const double zero[6] = {0, 0, 0, 0, 0, 0};
  double residual = 0.0;
  PairCost(X, hand_motion, pair)(zero, &residual);
  return residual;
}

EpipolarPolish PolishEpipolar(const global::EpipolarProblem& problem, const Pose& start,
                              std::optional<double> ray_sigma) {
  const int n = global::PairCount(problem);
  if (n < 7) {
    throw DegenerateError(
        "the hand–eye transform (6 unknowns) from " + std::to_string(n) + " bearing pairs",
        "give at least 7 point matches");
  }
  Pose X = start;
  // Two rounds: the second re-centres δ at the first round's solution, so the Jacobian the
  // covariance uses is taken at δ = 0 of the final X.
  Eigen::MatrixXd J(n, 6);
  Eigen::VectorXd r(n);
  for (int round = 0; round < 2; ++round) {
    double delta[6] = {0, 0, 0, 0, 0, 0};
    ceres::Problem ceres_problem;
    for (const global::EpipolarMotion& motion : problem.motions) {
      for (const global::BearingPair& pair : motion.pairs) {
        ceres_problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<PairCost, 1, 6>(new PairCost(X, motion.hand, pair)),
            nullptr, delta);
      }
    }
    if (round == 0) {
      ceres::Solver::Options options;
      options.max_num_iterations = 100;
      options.function_tolerance = 1e-14;
      options.parameter_tolerance = 1e-14;
      options.gradient_tolerance = 1e-16;
      ceres::Solver::Summary summary;
      ceres::Solve(options, &ceres_problem, &summary);
      X = Apply(X, delta);
      continue;
    }
    ceres::CRSMatrix jacobian;
    std::vector<double> residuals;
    ceres_problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, &residuals, nullptr,
                           &jacobian);
    J.setZero();
    for (int row = 0; row < jacobian.num_rows; ++row) {
      for (int k = jacobian.rows[row]; k < jacobian.rows[row + 1]; ++k) {
        J(row, jacobian.cols[k]) = jacobian.values[k];
      }
      r[row] = residuals[row];
    }
  }
  EpipolarPolish polish;
  polish.X = X;
  polish.pairs = n;
  polish.rms = std::sqrt(r.squaredNorm() / n);
  polish.ray_sigma = ray_sigma ? *ray_sigma : std::sqrt(r.squaredNorm() / (n - 6));
  // δ = (ω, τ) with t = t̂ + R̂ τ: to first order τ is the v of the right perturbation
  // X̂ · Exp(ω, v), whose translation is t̂ + R̂ J(ω) v.
  const Matrix6d information = J.transpose() * J;
  polish.covariance = polish.ray_sigma * polish.ray_sigma * Matrix6d(information.inverse());
  return polish;
}

RecheckedPolish PolishAndRecheck(const global::EpipolarProblem& all,
                                 const global::EpipolarProblem& inliers, const Pose& start,
                                 std::optional<double> ray_sigma, double k) {
  RecheckedPolish result;
  result.inliers = inliers;
  result.polish = PolishEpipolar(inliers, start, ray_sigma);
  for (int round = 0; round < 5; ++round) {
    double sigma = 0.0;
    if (ray_sigma) {
      sigma = *ray_sigma;
    } else {
      std::vector<double> kept;
      for (const global::EpipolarMotion& motion : result.inliers.motions) {
        for (const global::BearingPair& pair : motion.pairs) {
          kept.push_back(std::abs(SampsonAngle(result.polish.X, motion.hand, pair)));
        }
      }
      std::nth_element(kept.begin(), kept.begin() + kept.size() / 2, kept.end());
      // At least 1e-8 rad (1e-5 px at f = 1000 px): below that the residuals of noise-free data
      // are rounding in the ray geometry, not a scale to test against.
      sigma = std::max(1e-8, 1.4826 * kept[kept.size() / 2]);
    }
    global::EpipolarProblem next = all;
    std::vector<std::pair<int, int>> removed;
    for (std::size_t m = 0; m < all.motions.size(); ++m) {
      std::vector<global::BearingPair>& pairs = next.motions[m].pairs;
      pairs.clear();
      for (const global::BearingPair& pair : all.motions[m].pairs) {
        if (std::abs(SampsonAngle(result.polish.X, all.motions[m].hand, pair)) <= k * sigma) {
          pairs.push_back(pair);
        } else {
          removed.emplace_back(int(m), pair.id);
        }
      }
    }
    if (removed == result.removed && round > 0) break;
    if (global::PairCount(next) < 7) break;  // keep the last usable set
    result.inliers = std::move(next);
    result.removed = std::move(removed);
    result.polish = PolishEpipolar(result.inliers, result.polish.X, ray_sigma);
  }
  return result;
}

}  // namespace hecal::estimation
