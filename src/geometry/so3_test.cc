#include "hecal/geometry/so3.h"

#include <gtest/gtest.h>

#include "testing/random_poses.h"

namespace hecal {
namespace {

TEST(So3, ExpLogRoundTripSmoke) {
  std::mt19937_64 rng(1);
  for (const Eigen::Vector3d& omega : testing::EdgeCaseRotationVectors(rng)) {
    const Eigen::Matrix3d R = so3::Exp(omega);
    EXPECT_LT((so3::Exp(so3::Log(R)) - R).norm(), 1e-14) << omega.transpose();
  }
}

}  // namespace
}  // namespace hecal
