#include "hecal/global/outlier_removal.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <random>

namespace hecal::global {
namespace {

double SampsonError(const Eigen::Matrix3d& E, const BearingPair& pair) {
  const Eigen::Vector3d v = pair.first.normalized(), u = pair.second.normalized();
  const Eigen::Vector3d Eu = E * u, Etv = E.transpose() * v;
  const double scale =
      std::sqrt((Eu - v * v.dot(Eu)).squaredNorm() + (Etv - u * u.dot(Etv)).squaredNorm());
  return scale > 0 ? std::abs(v.dot(Eu)) / scale : M_PI / 2;
}

// The least-squares E (unit Frobenius norm) from the pairs `sample`.
Eigen::Matrix3d EightPoint(const std::vector<BearingPair>& pairs, const std::vector<int>& sample) {
  Eigen::MatrixXd A(sample.size(), 9);
  for (std::size_t k = 0; k < sample.size(); ++k) {
    const Eigen::Vector3d v = pairs[sample[k]].first, u = pairs[sample[k]].second;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) A(k, 3 * i + j) = v[i] * u[j];
    }
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::VectorXd e = svd.matrixV().col(8);
  Eigen::Matrix3d E;
  E << e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8];
  return E;
}

}  // namespace

EpipolarProblem PrefilterPairs(const EpipolarProblem& problem, const OutlierOptions& options,
                               std::vector<RemovedPair>* removed) {
  EpipolarProblem kept = problem;
  std::mt19937_64 rng(options.seed);
  for (std::size_t m = 0; m < problem.motions.size(); ++m) {
    const std::vector<BearingPair>& pairs = problem.motions[m].pairs;
    const int n = int(pairs.size());
    if (n < 9) continue;  // too few to tell: the L∞ stage decides
    std::vector<int> best;
    std::vector<int> indices(n);
    for (int i = 0; i < n; ++i) indices[i] = i;
    for (int iteration = 0; iteration < options.ransac_iterations; ++iteration) {
      std::shuffle(indices.begin(), indices.end(), rng);
      const Eigen::Matrix3d E = EightPoint(pairs, {indices.begin(), indices.begin() + 8});
      std::vector<int> inliers;
      for (int i = 0; i < n; ++i) {
        if (SampsonError(E, pairs[i]) <= options.threshold) inliers.push_back(i);
      }
      if (inliers.size() > best.size()) best = inliers;
    }
    // Refit on the consensus set and re-score once.
    if (best.size() >= 8) {
      const Eigen::Matrix3d E = EightPoint(pairs, best);
      best.clear();
      for (int i = 0; i < n; ++i) {
        if (SampsonError(E, pairs[i]) <= options.threshold) best.push_back(i);
      }
    }
    std::vector<char> keep(n, 0);
    for (int i : best) keep[i] = 1;
    std::vector<BearingPair>& out = kept.motions[m].pairs;
    out.clear();
    for (int i = 0; i < n; ++i) {
      if (keep[i]) {
        out.push_back(pairs[i]);
      } else if (removed) {
        removed->push_back({int(m), pairs[i].id, true});
      }
    }
  }
  return kept;
}

RobustGlobalSolution SolveGlobalRobust(const EpipolarProblem& problem, const SearchOptions& search,
                                       const OutlierOptions& options) {
  RobustGlobalSolution result;
  result.inliers = PrefilterPairs(problem, options, &result.removed);
  // The rounds only need to tell whether the optimum exceeds the threshold: they stop at an X
  // within it, or close the gap to a quarter of it; the last solve closes the requested gap.
  SearchOptions round_options = search;
  round_options.epsilon = std::max(search.epsilon, 0.25 * options.threshold);
  round_options.stop_below = options.threshold;
  while (true) {
    result.solution = SolveGlobal(result.inliers, round_options);
    ++result.rounds;
    const double optimum = result.solution.certificate.upper;
    if (optimum <= options.threshold || result.solution.certificate.lower <= options.threshold ||
        result.rounds >= options.max_rounds) {
      break;
    }
    // The support set: the pairs at the optimum's error.
    const auto errors = RayErrors(result.inliers, result.solution.X);
    const double level = optimum - std::max(search.epsilon, 1e-9 * optimum);
    for (std::size_t m = 0; m < errors.size(); ++m) {
      std::vector<BearingPair>& pairs = result.inliers.motions[m].pairs;
      std::vector<BearingPair> kept;
      for (std::size_t j = 0; j < pairs.size(); ++j) {
        if (errors[m][j] >= level) {
          result.removed.push_back({int(m), pairs[j].id, false});
        } else {
          kept.push_back(pairs[j]);
        }
      }
      pairs = std::move(kept);
    }
    round_options.start = result.solution.X;
  }
  const Certificate& last = result.solution.certificate;
  if (last.upper - last.lower > std::max(search.epsilon, search.relative_gap * last.upper)) {
    SearchOptions final_options = search;
    final_options.start = result.solution.X;
    result.solution = SolveGlobal(result.inliers, final_options);
    ++result.rounds;
  }
  return result;
}

}  // namespace hecal::global
