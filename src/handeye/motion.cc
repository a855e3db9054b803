#include "hecal/handeye/motion.h"

namespace hecal::handeye {

std::vector<Motion> AllPairMotions(const Problem& problem) {
  const int n = static_cast<int>(problem.A.size());
  std::vector<Motion> motions;
  motions.reserve(static_cast<size_t>(n) * static_cast<size_t>(n > 0 ? n - 1 : 0) / 2);
  std::vector<Pose> A_inverse(problem.A.size());
  std::vector<Pose> B_inverse(problem.B.size());
  for (int i = 0; i < n; ++i) {
    A_inverse[i] = problem.A[i].inverse();
    B_inverse[i] = problem.B[i].inverse();
  }
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      motions.push_back({A_inverse[j] * problem.A[i], problem.B[j] * B_inverse[i], i, j});
    }
  }
  return motions;
}

}  // namespace hecal::handeye
