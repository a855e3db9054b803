#include "hecal/estimation/epipolar_polish.h"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <algorithm>
#include <cmath>

#include "epipolar_residual.h"
#include "hecal/core/error.h"

namespace hecal::estimation {
namespace {

// Residual of one pair as a function of δ = (ω, τ): R = R̂ Exp(ω), t = t̂ + R̂ τ.
struct PairCost {
  PairCost(const Pose& X0, const Pose& B, const global::BearingPair& pair)
      : X0_(X0), B_(B), pair_(pair) {}

  template <typename T>
  bool operator()(const T* delta, T* residual) const {
    residual[0] = detail::SampsonResidual<T>(X0_, B_, pair_, delta, nullptr, nullptr);
    return true;
  }

  Pose X0_, B_;
  global::BearingPair pair_;
};

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
      X = detail::ApplyDelta(X, delta);
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
