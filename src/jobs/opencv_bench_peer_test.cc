// The benchmark's OpenCV peer on noise-free data sets of the bench protocol: for the methods
// OpenCV implements it returns the true X (both OpenCV functions, both setups); for the others
// (strobl, ml, closed forms OpenCV lacks) it has no solver.
#include "hecal/jobs/opencv_bench_peer.h"

#include <gtest/gtest.h>

#include <optional>
#include <vector>

namespace hecal::jobs {
namespace {

using estimation::Method;

TEST(OpenCvBenchPeer, SolvesNoiseFreeDataSetsToTheTruth) {
  const study::BenchPeer peer = OpenCvBenchPeer();
  EXPECT_EQ(peer.name, "opencv");
  for (const handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const std::vector<study::BenchDataSet> sets =
        study::MakeBenchDataSets(setup, 10, 3, study::NoiseLevel{0.0, 0.0}, 7);
    // park-martin: cv::calibrateHandEye; li: cv::calibrateRobotWorldHandEye.
    for (const Method method : {Method::kParkMartin, Method::kLi}) {
      ASSERT_TRUE(HasOpenCvBenchPeer(method));
      const std::optional<study::BenchSolver> solve = peer.prepare(method, sets);
      ASSERT_TRUE(solve.has_value());
      for (std::size_t i = 0; i < sets.size(); ++i) {
        const Pose X = (*solve)(i);
        const Pose& truth = sets[i].data.X;
        EXPECT_TRUE(X.linear().isApprox(truth.linear(), 1e-6))
            << estimation::Info(method).name << " set " << i;
        EXPECT_LT((X.translation() - truth.translation()).norm(), 1e-6)
            << estimation::Info(method).name << " set " << i;
      }
    }
  }
}

TEST(OpenCvBenchPeer, HasNoSolverForMethodsOpenCvLacks) {
  const std::vector<study::BenchDataSet> sets =
      study::MakeBenchDataSets(handeye::Setup::kEyeInHand, 5, 1, study::NoiseLevel{0.1, 0.1}, 1);
  for (const Method method : {Method::kShiuAhmad, Method::kStrobl, Method::kMl}) {
    EXPECT_FALSE(HasOpenCvBenchPeer(method)) << estimation::Info(method).name;
    EXPECT_FALSE(OpenCvBenchPeer().prepare(method, sets).has_value())
        << estimation::Info(method).name;
  }
}

}  // namespace
}  // namespace hecal::jobs
