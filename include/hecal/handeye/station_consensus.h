// The stations that agree on one (X, Z), found without knowing the noise level: least median of
// squares over minimal station sets with a local refit, the robust first stage of hecal's outlier
// rejection (estimation/station_selection.h) and the fit measure of the convention diagnosis
// (convention_diagnosis.h).
//
// Hypotheses (Fischler and Bolles, "Random sample consensus", CACM 24(6), 1981): minimal sets of
// 3 stations — two motions with non-parallel rotation axes fix X and Z — each solved in closed
// form from its two motions (minimal_solution.h: a few hundred operations, where Shah's solver on
// the triple, used before, spends most of its time on a 9 × 9 eigendecomposition). A
// triple whose rotations do not fix X (minimal_solution.h returns none) is skipped.
// How many (RequiredHypotheses): the breakdown point to support is the rejection limit of
// estimation/station_selection.h, m = ⌊(n − 3)/2⌋ arbitrary stations. A uniformly drawn triple
// of distinct stations is then clean with probability p = C(n − m, 3) / C(n, 3) (→ 1/8 for large
// n). The standard RANSAC / LMedS count (Fischler and Bolles; Rousseeuw and Leroy, "Robust
// regression and outlier detection", 1987, ch. 5) is the N with P(no clean triple) = (1 − p)^N
// ≤ δ. A clean triple can still be poorly conditioned (nearly parallel relative rotation axes,
// noise of the order of the rotations), so hecal asks for a floor of 5 clean triples, not one:
// N is the smallest count with P(Binomial(N, p) < 5) ≤ δ = 1e-9 at that m — 149 at n = 20,
// 197 at n = 50, 238 for large n — whatever the actual contamination. Every triple is solved when
// there are no more than N (n ≤ 9), else N random triples drawn with SplitMix64 from `seed`
// (deterministic); `max_hypotheses` caps N. Before, a fixed 1000 triples (n > 18) made the
// consensus 8.5 ms of the 11 ms outlier rejection at n = 50.
//
// Score (Rousseeuw, "Least median of squares regression", JASA 79, 1984): station i's residual
// under (X, Z) is E_i = Z⁻¹ · A_i · X · B_i (problem.h), of rotation angle a_i and translation
// length d_i, combined as e_i² = a_i² + (d_i / L)² with L = LengthScale (the camera-to-target
// distance, which is how far a rotation error of the camera moves the target). The hypothesis of
// least median e² wins: no noise level is needed and up to half the stations may be arbitrary.
// The hypotheses are ranked by the chordal form, a_i² replaced by (2 sin(a_i/2))² = 3 − tr R_i
// (no atan2, no square root: half the scoring cost, the consensus at n = 50 from 1.7 to
// 1.35 ms): it is monotone in a_i and equal to a_i² to a relative 1 − a_i²/12 (0.25% at 10°),
// and the median station of a hypothesis that can win is an inlier at the noise level, so the
// ranking is that of e² to well below the noise. It is evaluated as 4 (1 − w_i²), w_i = cos(a_i/2)
// a bilinear form in the station's quaternions with a 4 × 4 matrix per hypothesis (20
// multiplications per station instead of 70 for the rotation matrices).
// The local refit and every reported residual use the angle itself. A hypothesis is dropped as
// soon as so many stations have e² at or above the best median so far that its own median cannot
// be lower (exact: the same hypothesis wins; most lose after about half the stations).
// Scores are computed on at most `max_scored_stations` stations (a fixed random subset for
// larger n), so the cost is O(hypotheses · min(n, max_scored_stations)).
//
// Local refit (Chum, Matas and Kittler, "Locally optimized RANSAC", DAGM 2003): the consensus set
// is {i : e_i ≤ κ · median(e)}, κ = 3 — for Gaussian noise e² ~ σ²·χ² with 3 to 6 degrees of
// freedom, and P(e > 3 · median) is 9e-5 (3) to 1e-8 (6) — widened to at least the
// n − ⌊(n − 3)/2⌋ stations of smallest e (with few stations three of them would otherwise be
// interpolated exactly and their median say nothing) and to e ≤ 1e-12 (rounding of the pose
// products, so that noise-free data are one set), and Shah is solved again on it, until the
// set stops changing (at most 10 rounds). The set is a candidate: the statistical test
// at the estimated noise (estimation/station_selection.h) has the last word.
//
// Residual angles use atan2(|vee(R − Rᵀ)|/2, (tr R − 1)/2), accurate near 0 and π.
// Throws DegenerateError (observability.h) when fewer than 3 stations are given or no triple
// fixes X.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hecal/handeye/problem.h"

namespace hecal::handeye {

struct ConsensusOptions {
  int max_hypotheses = 1000;       // cap on RequiredHypotheses(n), at least 1
  int max_scored_stations = 2000;  // at least 3 (one minimal set)
  std::uint64_t seed = 1;

  // core/options_check.h: false naming ConsensusOptions.max_hypotheses or
  // .max_scored_stations below their least values.
  bool IsValid(std::string* why) const;
};

struct StationConsensus {
  Solution solution;                // Shah on the consensus set
  std::vector<bool> inlier;         // the consensus set, one flag per station
  std::vector<double> rotation;     // a_i at `solution`, radians
  std::vector<double> translation;  // d_i at `solution`, metres
  // Medians of a_i and d_i over ALL stations at `solution`: the data's residual level, robust to
  // fewer than half gross outliers (the convention diagnosis compares these).
  double median_rotation = 0.0;
  double median_translation = 0.0;
  int hypotheses = 0;  // triples solved
};

StationConsensus FindStationConsensus(const Problem& problem, const ConsensusOptions& options);

// N above: the number of random triples for n stations (0 for n < 3).
int RequiredHypotheses(int n);

// a_i and d_i of one station under (X, Z), as above.
struct StationError {
  double rotation = 0.0;
  double translation = 0.0;
};
StationError StationResidualSize(const Problem& problem, size_t station, const Solution& solution);

// The stations of `problem` whose flag is set, in order.
Problem SubProblem(const Problem& problem, const std::vector<bool>& keep);

}  // namespace hecal::handeye
