// MeanOptions::IsValid (manifold.h): the defaults are valid, each bad field is named, and
// WeightedMean refuses bad options before it iterates.
#include "hecal/uncertainty/manifold.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "hecal/core/error.h"
#include "testing/options_validity.h"

namespace hecal::uncertainty {
namespace {

TEST(MeanOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const MeanOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(
      RefusesNaming(defaults, "MeanOptions.max_iterations", [](auto& o) { o.max_iterations = 0; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "MeanOptions.tolerance", [](auto& o) { o.tolerance = -1.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "MeanOptions.tolerance", [](auto& o) {
    o.tolerance = std::numeric_limits<double>::quiet_NaN();
  }));
  const std::vector<Eigen::VectorXd> points = {Eigen::VectorXd::Zero(2)};
  const std::vector<double> weights = {1.0};
  MeanOptions bad;
  bad.max_iterations = 0;
  EXPECT_THROW(WeightedMean<Eigen::VectorXd>(points, weights, points[0], bad), InputError);
}

}  // namespace
}  // namespace hecal::uncertainty
