#include "hecal/handeye/motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "testing/handeye_cases.h"

namespace hecal::handeye {
namespace {

// Noise-free, every motion of every pair satisfies A_ij X = X B_ij with the definitions of
// motion.h (A_ij = A_j⁻¹ A_i, B_ij = B_j B_i⁻¹), in both setups.
TEST(AllPairMotions, EveryPairOnceAndConjugate) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::Scene data = testing::ThesisCase(setup, 7, 3);
    const Problem problem = data.MeasuredProblem();
    const std::vector<Motion> motions = AllPairMotions(problem);
    ASSERT_EQ(motions.size(), 21u);
    std::set<std::pair<int, int>> seen;
    for (const Motion& m : motions) {
      EXPECT_LT(m.i, m.j);
      seen.insert({m.i, m.j});
      const size_t i = static_cast<size_t>(m.i), j = static_cast<size_t>(m.j);
      EXPECT_TRUE(m.A.isApprox(problem.A[j].inverse() * problem.A[i], 1e-12));
      EXPECT_TRUE(m.B.isApprox(problem.B[j] * problem.B[i].inverse(), 1e-12));
      EXPECT_TRUE((m.A * data.X).isApprox(data.X * m.B, 1e-9));
    }
    EXPECT_EQ(seen.size(), 21u);
  }
}

// Up to the budget (n = 632: 199,396 pairs) StationPairs is every pair; one station more
// (200,028 > kMaxAllPairs) switches to the subsample.
TEST(StationPairs, AllPairsUpToTheBudget) {
  for (int n : {0, 1, 2, 3, 50, 632}) {
    const std::vector<StationPair> pairs = StationPairs(n);
    ASSERT_EQ(pairs.size(), n < 2 ? 0u : static_cast<size_t>(n) * (n - 1) / 2) << n;
    size_t k = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j, ++k) {
        EXPECT_EQ(pairs[k].i, i);
        EXPECT_EQ(pairs[k].j, j);
      }
  }
  EXPECT_LT(StationPairs(633).size(), 633u * 632u / 2u);
}

// Above the budget: sorted, unique pairs i < j, every station in at least k of them, and the
// total between n·k/2 and n·k — linear in n.
TEST(StationPairs, SubsampleGivesEveryStationItsPartners) {
  for (int n : {633, 5000, 30000}) {
    const size_t k = std::max(static_cast<size_t>(kMinPartners),
                              (kMaxAllPairs + static_cast<size_t>(n) - 1) / static_cast<size_t>(n));
    const std::vector<StationPair> pairs = StationPairs(n);
    std::vector<size_t> degree(static_cast<size_t>(n), 0);
    for (size_t p = 0; p < pairs.size(); ++p) {
      ASSERT_LT(pairs[p].i, pairs[p].j);
      ASSERT_GE(pairs[p].i, 0);
      ASSERT_LT(pairs[p].j, n);
      if (p > 0) {
        ASSERT_TRUE(pairs[p - 1].i < pairs[p].i ||
                    (pairs[p - 1].i == pairs[p].i && pairs[p - 1].j < pairs[p].j))
            << "not sorted and unique at " << p;
      }
      ++degree[static_cast<size_t>(pairs[p].i)];
      ++degree[static_cast<size_t>(pairs[p].j)];
    }
    EXPECT_GE(*std::min_element(degree.begin(), degree.end()), k) << n;
    EXPECT_GE(pairs.size(), static_cast<size_t>(n) * k / 2) << n;
    EXPECT_LE(pairs.size(), static_cast<size_t>(n) * k) << n;
  }
}

}  // namespace
}  // namespace hecal::handeye
