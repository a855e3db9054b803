// Relative motions for the AX = XB solvers, from station pairs.
//
// From Z = A_i X B_i = A_j X B_j (problem.h):   A_ij · X = X · B_ij   with
//        A_ij = A_j⁻¹ · A_i,      B_ij = B_j · B_i⁻¹.
// (Eye-in-hand: A_ij is the gripper motion, B_ij the camera motion — OpenCV's calibrateHandEye
// convention with X = cam2gripper.) Noise-free, A_ij and B_ij are conjugate: same rotation angle
// and same translation along the axis (the screw invariants Daniilidis checks). Every solver
// accumulates its normal equations over the motions (small fixed-size operations, no large
// matrix), so its cost and memory are linear in the number of motions.
//
// Which pairs (StationPairs, what the dispatcher closed_form.h uses):
//  - every pair i < j while there are at most kMaxAllPairs of them (n ≤ 632 stations; the
//    tables of docs/accuracy.md, n ≤ 50, and `hecal bench` are all-pairs exactly);
//  - above, a subsample linear in n: every station i draws k = max(kMinPartners,
//    ⌈kMaxAllPairs / n⌉) distinct partners j ≠ i uniformly from a SplitMix64 stream keyed by i
//    (fixed, so the closed forms stay deterministic functions of the data), and each unordered
//    pair is kept once — between n·k/2 and n·k pairs, every station in at least k of them.
//    n = 10³: k = 200; 10⁴: k = 20, ~2·10⁵ pairs; 10⁵: k = 20, ~2·10⁶ pairs (264 bytes each,
//    ~0.5 GB) instead of 5·10⁹.
// Why uniform random partners: the all-pairs estimate weights each station's noise by the
// average of its gains over all partners; k random partners estimate that average with a
// relative error ~1/√k, which adds a variance fraction of about 1/k on top of an estimate whose
// variance already falls as 1/n — on a 10⁴-station data set (σ = 1 mm / 1°) the eight
// subsampled closed forms are within 1.4–1.9× the first-order bound in rotation (docs/speed.md,
// Scale). A rule that preferred large relative
// rotations would need the rotations of all n² pairs to rank, and a rule tied to the station
// order (neighbours i ± 1 …) could be fooled by a periodic or drifting station sequence.
#pragma once

#include <cstddef>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"

namespace hecal::handeye {

inline constexpr size_t kMaxAllPairs = 200000;
inline constexpr int kMinPartners = 20;

struct StationPair {
  int i = 0;  // i < j
  int j = 0;
};

struct Motion {
  Pose A;     // A_ij
  Pose B;     // B_ij
  int i = 0;  // station indices, i < j
  int j = 0;
};

// The pairs of n stations by the rule above, sorted by (i, j), each once.
std::vector<StationPair> StationPairs(int n);

// The motions of the given pairs.
std::vector<Motion> PairMotions(const Problem& problem, const std::vector<StationPair>& pairs);

// PairMotions(problem, StationPairs(n)): what the AX = XB methods solve.
std::vector<Motion> StationPairMotions(const Problem& problem);

// Every pair whatever n (n(n−1)/2 motions): the reference the subsample is measured against.
std::vector<Motion> AllPairMotions(const Problem& problem);

}  // namespace hecal::handeye
