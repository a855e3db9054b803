#include "hecal/study/bench.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/core/error.h"

namespace hecal::study {
namespace {

void ExpectInvalid(const std::function<void(BenchOptions&)>& spoil, const std::string& field,
                   const std::string& problem) {
  BenchOptions options;
  spoil(options);
  std::string why;
  EXPECT_FALSE(options.IsValid(&why)) << field;
  EXPECT_EQ(why.rfind("BenchOptions." + field + ": ", 0), 0u) << why;
  EXPECT_NE(why.find(problem), std::string::npos) << why;
  try {
    RunBench(options);
    ADD_FAILURE() << "RunBench accepted a bad " << field;
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "BenchOptions." + field);
  }
}

TEST(BenchOptions, DefaultsAreValid) {
  std::string why;
  EXPECT_TRUE(BenchOptions().IsValid(&why)) << why;
}

TEST(BenchOptions, EachCheckedFieldRejectsABadValue) {
  ExpectInvalid([](BenchOptions& o) { o.stations.clear(); }, "stations", "no station count");
  ExpectInvalid(
      [](BenchOptions& o) {
        o.stations = {10, 2};
      },
      "stations", "'2' is outside the range 3 to 100000");
  ExpectInvalid([](BenchOptions& o) { o.methods.clear(); }, "methods", "no method");
  ExpectInvalid([](BenchOptions& o) { o.datasets = 0; }, "datasets", "from 1 to 10000, got 0");
  ExpectInvalid([](BenchOptions& o) { o.datasets = 10001; }, "datasets", "from 1 to 10000");
  // 100000 stations × 100 data sets = 10^7 poses.
  ExpectInvalid(
      [](BenchOptions& o) {
        o.stations = {100000};
        o.datasets = 100;
      },
      "datasets", "poses, the most hecal bench generates");
  ExpectInvalid([](BenchOptions& o) { o.min_time = -1.0; }, "min_time", "0 to 3600 seconds");
  ExpectInvalid([](BenchOptions& o) { o.min_time = std::numeric_limits<double>::quiet_NaN(); },
                "min_time", "seconds");
  ExpectInvalid([](BenchOptions& o) { o.sigma = {1001.0, 0.1}; }, "sigma", "0 to 1000 mm");
  ExpectInvalid([](BenchOptions& o) { o.sigma = {0.1, -1.0}; }, "sigma", "0 to 180 deg");
}

TEST(MakeBenchDataSets, TheSimulateStudysDataForTheSameSeed) {
  const std::vector<BenchDataSet> a =
      MakeBenchDataSets(handeye::Setup::kEyeInHand, 5, 3, {0.0, 0.0}, 7);
  const std::vector<BenchDataSet> b =
      MakeBenchDataSets(handeye::Setup::kEyeInHand, 5, 3, {0.0, 0.0}, 7);
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].problem.A.size(), 5u);
  EXPECT_TRUE(a[2].data.X.isApprox(b[2].data.X, 0.0));
  EXPECT_FALSE(a[0].data.X.isApprox(a[1].data.X, 1e-6));
}

// Noise-free data: every hecal solver and the good start give the truth; the rows come in the
// documented order and a peer that has no method adds no row.
TEST(RunBench, NoiseFreeDataAreSolvedExactlyInRowOrder) {
  BenchOptions options;
  options.stations = {5};
  options.datasets = 2;
  options.sigma = {0.0, 0.0};
  options.min_time = 0.0;
  options.methods = {estimation::Method::kParkMartin, estimation::Method::kMl};
  BenchPeer peer;
  peer.name = "peer";
  int prepared = 0;
  peer.prepare = [&prepared](estimation::Method method,
                             const std::vector<BenchDataSet>& sets) -> std::optional<BenchSolver> {
    ++prepared;
    if (method != estimation::Method::kParkMartin) return std::nullopt;
    return [&sets](std::size_t i) { return sets[i].data.X; };
  };
  const BenchResult result = RunBench(options, peer);
  EXPECT_EQ(prepared, 2);
  ASSERT_EQ(result.rows.size(), 4u);
  EXPECT_EQ(result.rows[0].impl, "hecal");
  EXPECT_EQ(result.rows[0].start, BenchStart::kNotApplicable);
  EXPECT_EQ(result.rows[1].impl, "peer");
  EXPECT_EQ(result.rows[2].start, BenchStart::kClosedForm);
  EXPECT_EQ(result.rows[3].start, BenchStart::kGood);
  for (const BenchRow& row : result.rows) {
    EXPECT_EQ(row.datasets, 2);
    EXPECT_EQ(row.accuracy.failures, 0);
    EXPECT_EQ(row.accuracy.finite, 2);
    ASSERT_TRUE(row.accuracy.rotation_error.has_value());
    EXPECT_LT(*row.accuracy.rotation_error, 1e-7);
    EXPECT_LT(*row.accuracy.translation_error, 1e-7);
    EXPECT_GT(row.us_per_solve, 0.0);
  }
}

TEST(MeasureAccuracy, CountsThrowsNonFiniteAndLargeErrorsAsFailures) {
  const std::vector<BenchDataSet> sets =
      MakeBenchDataSets(handeye::Setup::kEyeInHand, 4, 3, {0.0, 0.0}, 1);
  const BenchAccuracy accuracy = MeasureAccuracy(sets, [&sets](std::size_t i) -> Pose {
    if (i == 0) throw std::runtime_error("no");
    if (i == 1) return Pose(Eigen::Matrix4d::Constant(std::numeric_limits<double>::quiet_NaN()));
    Pose X = sets[i].data.X;
    X.translation().x() += 0.003;  // 3 mm off
    return X;
  });
  EXPECT_EQ(accuracy.failures, 2);
  EXPECT_EQ(accuracy.finite, 1);
  EXPECT_NEAR(*accuracy.translation_error, 0.003, 1e-12);
  EXPECT_NEAR(*accuracy.rotation_error, 0.0, 1e-12);
}

}  // namespace
}  // namespace hecal::study
