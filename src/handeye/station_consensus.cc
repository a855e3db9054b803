#include "hecal/handeye/station_consensus.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/core/split_mix.h"
#include "hecal/geometry/rotation.h"
#include "hecal/handeye/minimal_solution.h"
#include "hecal/handeye/observability.h"
#include "hecal/handeye/shah.h"

namespace hecal::handeye {
namespace {

constexpr double kInlierFactor = 3.0;  // κ: consensus set e_i ≤ κ · median(e)
constexpr int kMaxRefitRounds = 10;
// e below this (radians, or translation / L) is the rounding of the pose products, not a residual:
// the consensus set's threshold is at least its square (header, "Local refit").
constexpr double kRoundingError = 1e-12;
constexpr int kMinCleanTriples = 5;        // the floor on clean hypotheses (header)
constexpr double kMissProbability = 1e-9;  // δ (header)

struct Triple {
  int a, b, c;
};

// P(fewer than kMinCleanTriples of `count` uniform random triples are clean) when `clean` is the
// probability that one is: the binomial tail, summed term by term.
double FewCleanProbability(int count, double clean) {
  double term = std::pow(1.0 - clean, count);  // P(0 clean)
  double sum = term;
  for (int j = 1; j < kMinCleanTriples && j <= count; ++j) {
    term *= static_cast<double>(count - j + 1) / j * clean / (1.0 - clean);
    sum += term;
  }
  return sum;
}

// Every triple when there are no more than RequiredHypotheses(n) (capped by max_hypotheses),
// else that many random distinct-member triples.
std::vector<Triple> Triples(int n, const ConsensusOptions& options) {
  std::vector<Triple> triples;
  const int count = std::min(RequiredHypotheses(n), options.max_hypotheses);
  const double all = static_cast<double>(n) * (n - 1) * (n - 2) / 6.0;
  if (all <= count) {
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        for (int c = b + 1; c < n; ++c) triples.push_back({a, b, c});
    return triples;
  }
  std::uint64_t state = options.seed;
  const auto draw = [&](int range) {
    state = SplitMix64(state);
    return static_cast<int>(state % static_cast<std::uint64_t>(range));
  };
  triples.reserve(static_cast<size_t>(count));
  while (static_cast<int>(triples.size()) < count) {
    const int a = draw(n), b = draw(n), c = draw(n);
    if (a != b && b != c && a != c) triples.push_back({a, b, c});
  }
  return triples;
}

// The stations the hypotheses are scored on: all, or a fixed random subset for large n.
std::vector<int> ScoredStations(int n, const ConsensusOptions& options) {
  std::vector<int> stations(n);
  for (int i = 0; i < n; ++i) stations[i] = i;
  if (n <= options.max_scored_stations) return stations;
  std::uint64_t state = SplitMix64(options.seed ^ 0x5eedULL);
  for (int i = 0; i < options.max_scored_stations; ++i) {  // partial Fisher–Yates
    state = SplitMix64(state);
    const int j = i + static_cast<int>(state % static_cast<std::uint64_t>(n - i));
    std::swap(stations[i], stations[j]);
  }
  stations.resize(options.max_scored_stations);
  return stations;
}

double SquaredError(const StationError& error, double length_scale) {
  const double d = error.translation / length_scale;
  return error.rotation * error.rotation + d * d;
}

// The median of `values` (which it reorders).
double Median(std::vector<double>& values) {
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle),
                   values.end());
  const double upper = values[middle];
  if (values.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle));
  return 0.5 * (lower + upper);
}

// The stations' rotations as unit quaternions (4-vectors, Eigen's x, y, z, w order), for the
// score's rotation term below: q_A⁻¹ and q_B of each station.
struct StationQuaternions {
  std::vector<Eigen::Vector4d> A_inverse, B;
};

StationQuaternions QuaternionsOf(const Problem& problem) {
  StationQuaternions q;
  q.A_inverse.reserve(problem.A.size());
  q.B.reserve(problem.B.size());
  for (size_t i = 0; i < problem.A.size(); ++i) {
    q.A_inverse.push_back(QuaternionFromMatrix(problem.A[i].linear().transpose()).coeffs());
    q.B.push_back(QuaternionFromMatrix(problem.B[i].linear()).coeffs());
  }
  return q;
}

// One hypothesis's part of the score. The rotation term (2 sin(a_i/2))² = 4 (1 − w_i²), with
// w_i = cos(a_i/2) the scalar part of q_Z⁻¹ q_A q_X q_B, which equals the 4-vector product
// ⟨q_A⁻¹ q_Z, q_X q_B⟩ (multiplying by a unit quaternion preserves the inner product); it is
// bilinear in the station's (q_A⁻¹, q_B), w_i = (q_A⁻¹)ᵀ M (q_B) with column j of M the
// quaternion (q_X E_j) q_Z⁻¹ (E_j the basis quaternions): 20 multiplications per station where
// the rotation matrices R_Z, R_A R_X R_B took 70.
struct HypothesisScore {
  Eigen::Matrix4d M;
  const Solution* solution;
};

HypothesisScore ScoreOf(const Solution& solution) {
  const Eigen::Quaterniond q_X = QuaternionFromMatrix(solution.X.linear());
  const Eigen::Quaterniond q_Z_inverse = QuaternionFromMatrix(solution.Z.linear()).conjugate();
  HypothesisScore score{Eigen::Matrix4d::Zero(), &solution};
  for (int j = 0; j < 4; ++j) {
    Eigen::Vector4d basis = Eigen::Vector4d::Zero();
    basis(j) = 1.0;
    score.M.col(j) = (q_X * Eigen::Quaterniond(basis) * q_Z_inverse).coeffs();
  }
  return score;
}

// The two terms of the hypothesis score of one station, the chordal form of e² (header,
// "Score"): (2 sin(a/2))² and (d / L)², no angle, no square root.
double ChordalRotationTerm(const StationQuaternions& q, int i, const HypothesisScore& hypothesis) {
  const double w = q.A_inverse[i].dot(hypothesis.M * q.B[i]);
  return std::max(0.0, 4.0 * (1.0 - w * w));
}

double ChordalTranslationTerm(const Problem& problem, int i, const HypothesisScore& hypothesis,
                              double length_scale) {
  const Solution& solution = *hypothesis.solution;
  // d = |R_Zᵀ t| = |t|: the rotation into Z's frame does not change the length.
  const Eigen::Vector3d t =
      problem.A[i].linear() *
          (solution.X.linear() * problem.B[i].translation() + solution.X.translation()) +
      problem.A[i].translation() - solution.Z.translation();
  return t.squaredNorm() / (length_scale * length_scale);
}

// The median of the chordal e² over `stations`, or +∞ as soon as that median is certain to be
// at least `bound` (so many stations have e² ≥ bound that the lower middle value is one of them):
// a hypothesis that cannot beat the best one so far is dropped after about half the stations.
// A station whose rotation term alone reaches the bound is counted without its translation
// term, which is added only if the median is needed after all.
double MedianSquaredErrorBelow(const Problem& problem, const StationQuaternions& q,
                               const std::vector<int>& stations, const Solution& solution,
                               double length_scale, double bound, std::vector<double>* scratch) {
  const HypothesisScore hypothesis = ScoreOf(solution);
  const size_t enough = stations.size() - (stations.size() - 1) / 2;
  size_t at_or_above = 0;
  scratch->clear();
  for (int i : stations) {
    double e2 = ChordalRotationTerm(q, i, hypothesis);
    if (e2 < bound) e2 += ChordalTranslationTerm(problem, i, hypothesis, length_scale);
    if (e2 >= bound && ++at_or_above >= enough) return std::numeric_limits<double>::infinity();
    scratch->push_back(e2);
  }
  for (size_t k = 0; k < stations.size(); ++k) {
    const int i = stations[k];
    if ((*scratch)[k] >= bound && ChordalRotationTerm(q, i, hypothesis) >= bound)
      (*scratch)[k] += ChordalTranslationTerm(problem, i, hypothesis, length_scale);
  }
  return Median(*scratch);
}

}  // namespace

int RequiredHypotheses(int n) {
  if (n < 3) return 0;
  const int outliers = std::max(0, (n - 3) / 2);
  // C(n − m, 3) / C(n, 3): the three distinct members all among the n − m good stations.
  double clean = 1.0;
  for (int j = 0; j < 3; ++j) clean *= static_cast<double>(n - outliers - j) / (n - j);
  if (clean >= 1.0) return kMinCleanTriples;
  int count = kMinCleanTriples;
  while (FewCleanProbability(count, clean) > kMissProbability) ++count;
  return count;
}

StationError StationResidualSize(const Problem& problem, size_t station, const Solution& solution) {
  const Pose E = solution.Z.inverse() * problem.A[station] * solution.X * problem.B[station];
  const Eigen::Matrix3d& R = E.linear();
  const Eigen::Vector3d vee(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));
  return {std::atan2(0.5 * vee.norm(), 0.5 * (R.trace() - 1.0)), E.translation().norm()};
}

Problem SubProblem(const Problem& problem, const std::vector<bool>& keep) {
  Problem sub;
  sub.setup = problem.setup;
  for (size_t i = 0; i < problem.A.size(); ++i) {
    if (!keep[i]) continue;
    sub.A.push_back(problem.A[i]);
    sub.B.push_back(problem.B[i]);
  }
  return sub;
}

bool ConsensusOptions::IsValid(std::string* why) const {
  if (max_hypotheses < 1) {
    return Invalid(why, "ConsensusOptions.max_hypotheses",
                   "must be at least 1, got " + std::to_string(max_hypotheses), "use e.g. 1000");
  }
  if (max_scored_stations < 3) {
    return Invalid(
        why, "ConsensusOptions.max_scored_stations",
        "must be at least 3 (one minimal set), got " + std::to_string(max_scored_stations),
        "use e.g. 2000");
  }
  return true;
}

StationConsensus FindStationConsensus(const Problem& problem, const ConsensusOptions& options) {
  RequireValid(options);
  const int n = static_cast<int>(problem.A.size());
  if (n < 3 || problem.B.size() != problem.A.size()) CheckObservability(problem);  // throws
  const double L = LengthScale(problem);
  const std::vector<int> scored = ScoredStations(n, options);
  std::vector<double> scratch;
  scratch.reserve(scored.size());
  const StationQuaternions quaternions = QuaternionsOf(problem);

  StationConsensus consensus;
  double best = std::numeric_limits<double>::infinity();
  for (const Triple& t : Triples(n, options)) {
    const std::optional<Solution> solution = SolveMinimal(problem, t.a, t.b, t.c);
    if (!solution) continue;  // these three stations do not fix X
    ++consensus.hypotheses;
    const double score =
        MedianSquaredErrorBelow(problem, quaternions, scored, *solution, L, best, &scratch);
    if (score < best) {
      best = score;
      consensus.solution = *solution;
    }
  }
  if (consensus.hypotheses == 0) CheckObservability(problem);  // throws: nothing fixes X
  if (consensus.hypotheses == 0) {
    throw DegenerateError("X (no three stations fix it)",
                          "rotate the robot about at least two clearly different axes");
  }

  // Local refit on the consensus set until it is stable. The set keeps at least the
  // n − ⌊(n − 3)/2⌋ best stations, so that with few stations it is a fit, not an interpolation
  // of three of them.
  std::vector<double> e2(n);
  const int min_count = n - (n - 3) / 2;
  consensus.inlier.assign(n, true);
  for (int round = 0; round <= kMaxRefitRounds; ++round) {
    for (int i = 0; i < n; ++i)
      e2[i] = SquaredError(StationResidualSize(problem, i, consensus.solution), L);
    scratch.assign(e2.begin(), e2.end());
    double threshold = kInlierFactor * kInlierFactor * Median(scratch);
    std::nth_element(scratch.begin(), scratch.begin() + (min_count - 1), scratch.end());
    threshold = std::max(
        {threshold, scratch[static_cast<size_t>(min_count - 1)], kRoundingError * kRoundingError});
    std::vector<bool> inlier(n);
    for (int i = 0; i < n; ++i) inlier[i] = e2[i] <= threshold;
    if (inlier == consensus.inlier && round > 0) break;
    consensus.inlier = inlier;
    if (round == kMaxRefitRounds) break;
    try {
      consensus.solution = SolveShah(SubProblem(problem, inlier));
    } catch (const DegenerateError&) {
      break;  // keep the last solution that was not degenerate
    }
  }

  consensus.rotation.resize(n);
  consensus.translation.resize(n);
  for (int i = 0; i < n; ++i) {
    const StationError error = StationResidualSize(problem, i, consensus.solution);
    consensus.rotation[i] = error.rotation;
    consensus.translation[i] = error.translation;
  }
  scratch = consensus.rotation;
  consensus.median_rotation = Median(scratch);
  scratch = consensus.translation;
  consensus.median_translation = Median(scratch);
  return consensus;
}

}  // namespace hecal::handeye
