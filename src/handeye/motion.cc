#include "hecal/handeye/motion.h"

#include <algorithm>
#include <cstdint>

#include "hecal/core/split_mix.h"

namespace hecal::handeye {
namespace {

constexpr std::uint64_t kPairStream = 0x7061697273ULL;  // "pairs": the partner stream's key

std::vector<StationPair> AllPairs(int n) {
  std::vector<StationPair> pairs;
  pairs.reserve(static_cast<size_t>(n) * static_cast<size_t>(n > 0 ? n - 1 : 0) / 2);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) pairs.push_back({i, j});
  return pairs;
}

}  // namespace

std::vector<StationPair> StationPairs(int n) {
  const size_t count = static_cast<size_t>(n);
  if (n < 2 || count * (count - 1) / 2 <= kMaxAllPairs) return AllPairs(n);
  const size_t partners =
      std::max(static_cast<size_t>(kMinPartners), (kMaxAllPairs + count - 1) / count);
  std::vector<StationPair> pairs;
  pairs.reserve(count * partners);
  std::vector<int> drawn;
  for (int i = 0; i < n; ++i) {
    std::uint64_t state = SplitMix64(kPairStream ^ static_cast<std::uint64_t>(i));
    drawn.clear();
    while (drawn.size() < partners) {
      state = SplitMix64(state);
      const int j = static_cast<int>(state % count);
      if (j == i || std::find(drawn.begin(), drawn.end(), j) != drawn.end()) continue;
      drawn.push_back(j);
      pairs.push_back({std::min(i, j), std::max(i, j)});
    }
  }
  const auto less = [](const StationPair& a, const StationPair& b) {
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  };
  const auto same = [](const StationPair& a, const StationPair& b) {
    return a.i == b.i && a.j == b.j;
  };
  std::sort(pairs.begin(), pairs.end(), less);
  pairs.erase(std::unique(pairs.begin(), pairs.end(), same), pairs.end());
  pairs.shrink_to_fit();
  return pairs;
}

std::vector<Motion> PairMotions(const Problem& problem, const std::vector<StationPair>& pairs) {
  std::vector<Pose> A_inverse(problem.A.size());
  std::vector<Pose> B_inverse(problem.B.size());
  for (size_t i = 0; i < problem.A.size(); ++i) {
    A_inverse[i] = problem.A[i].inverse();
    B_inverse[i] = problem.B[i].inverse();
  }
  std::vector<Motion> motions;
  motions.reserve(pairs.size());
  for (const StationPair& pair : pairs) {
    const size_t i = static_cast<size_t>(pair.i), j = static_cast<size_t>(pair.j);
    motions.push_back({A_inverse[j] * problem.A[i], problem.B[j] * B_inverse[i], pair.i, pair.j});
  }
  return motions;
}

std::vector<Motion> StationPairMotions(const Problem& problem) {
  return PairMotions(problem, StationPairs(static_cast<int>(problem.A.size())));
}

std::vector<Motion> AllPairMotions(const Problem& problem) {
  return PairMotions(problem, AllPairs(static_cast<int>(problem.A.size())));
}

}  // namespace hecal::handeye
