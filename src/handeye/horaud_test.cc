#include "hecal/handeye/horaud.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <vector>

#include "hecal/geometry/so3.h"
#include "hecal/handeye/rotation_init.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

// f₁(R) = Σ ‖a_v − R b_v‖² with the motion quaternions' vector parts (signs aligned for R):
// the cost Horaud–Dornaika's eigenvector minimises (up to a constant).
double F1(const std::vector<Motion>& motions, const Eigen::Matrix3d& R) {
  double sum = 0.0;
  for (const Motion& motion : motions) {
    const AlignedQuaternions q = AlignQuaternions(motion, R);
    sum += (q.a.vec() - R * q.b.vec()).squaredNorm();
  }
  return sum;
}

// On noisy data the returned rotation is the minimiser of f₁: every small rotation of it (in 200
// random directions) costs more.
TEST(Horaud, RotationMinimisesTheQuaternionCost) {
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const testing::Scene data = testing::ThesisCase(Setup::kEyeInHand, 8, 900 + seed,
                                                    0.5 * std::numbers::pi / 180.0, 0.5e-3);
    const std::vector<Motion> motions = AllPairMotions(data.MeasuredProblem());
    const Eigen::Matrix3d R = SolveHoraud(motions).linear();
    const double best = F1(motions, R);
    std::mt19937_64 rng(seed);
    for (int k = 0; k < 200; ++k) {
      const Eigen::Matrix3d perturbed = R * so3::Exp(testing::RandomRotationVector(rng, 1e-4));
      EXPECT_GT(F1(motions, perturbed), best);
    }
    // …and the truth itself is worse than the estimate (the estimator is not cheating).
    EXPECT_GT(F1(motions, data.X.linear()), best);
  }
}

}  // namespace
}  // namespace hecal::handeye
