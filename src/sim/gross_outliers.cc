#include "hecal/sim/gross_outliers.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "hecal/core/random_draws.h"

namespace hecal::sim {

std::vector<int> InjectGrossOutliers(SimulatedData* data, int count, std::mt19937_64& rng) {
  const int n = static_cast<int>(data->T_base_gripper.size());
  if (count < 0 || count > n) {
    throw std::invalid_argument("InjectGrossOutliers: count must be within [0, stations]");
  }
  std::vector<int> stations(static_cast<size_t>(n));
  std::iota(stations.begin(), stations.end(), 0);
  for (int i = 0; i < count; ++i) {  // partial Fisher–Yates
    std::uniform_int_distribution<int> pick(i, n - 1);
    std::swap(stations[static_cast<size_t>(i)], stations[static_cast<size_t>(pick(rng))]);
  }
  stations.resize(static_cast<size_t>(count));
  std::sort(stations.begin(), stations.end());
  hecal::NormalDistribution gaussian;
  hecal::UniformRealDistribution box(-1.0, 1.0);
  for (int i : stations) {
    // One draw at a time, last component first (the order of the data sets' first generation).
    Eigen::Quaterniond q;
    do {
      const double z = gaussian(rng);
      const double y = gaussian(rng);
      const double x = gaussian(rng);
      const double w = gaussian(rng);
      q = Eigen::Quaterniond(w, x, y, z);
    } while (q.norm() < 1e-6);
    const double tz = box(rng);
    const double ty = box(rng);
    const double tx = box(rng);
    const Eigen::Vector3d t(tx, ty, tz);
    data->T_base_gripper[static_cast<size_t>(i)] = MakePose(q.normalized().toRotationMatrix(), t);
  }
  return stations;
}

}  // namespace hecal::sim
