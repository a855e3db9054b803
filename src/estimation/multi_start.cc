#include "multi_start.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"

namespace hecal::estimation::internal {
namespace {

bool Near(const Pose& a, const Pose& b, double rotation, double translation) {
  return so3::Distance(a.linear(), b.linear()) < rotation &&
         (a.translation() - b.translation()).norm() < translation;
}

}  // namespace

bool NearSolution(const handeye::Solution& a, const handeye::Solution& b, double rotation,
                  double translation) {
  return Near(a.X, b.X, rotation, translation) && Near(a.Z, b.Z, rotation, translation);
}

MultiStartResult RunMultiStart(const std::vector<handeye::Solution>& starts, double length_scale,
                               const std::function<double(const handeye::Solution&)>& evaluate,
                               const std::function<Optimum(const handeye::Solution&)>& refine) {
  std::vector<double> initial(starts.size());
  for (size_t i = 0; i < starts.size(); ++i) initial[i] = evaluate(starts[i]);
  std::vector<size_t> order(starts.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return initial[a] < initial[b]; });
  MultiStartResult result;
  std::vector<Optimum> optima;
  for (size_t index : order) {
    const handeye::Solution& start = starts[index];
    const bool in_known_basin = std::any_of(optima.begin(), optima.end(), [&](const Optimum& o) {
      return NearSolution(start, o.solution, kBasinRotation, kBasinTranslation * length_scale);
    });
    if (in_known_basin) continue;
    ++result.starts_refined;
    const Optimum optimum = refine(start);
    if (!std::isfinite(optimum.value)) continue;
    const bool known = std::any_of(optima.begin(), optima.end(), [&](const Optimum& o) {
      return NearSolution(optimum.solution, o.solution, kSameRotation,
                          kSameTranslation * length_scale);
    });
    if (!known) optima.push_back(optimum);
  }
  if (optima.empty()) {
    throw DegenerateError(
        "X and Z: the refinement failed (a non-finite cost) from every starting point",
        "check the data for poses far outside the robot's reach or lengths in the wrong unit");
  }
  result.distinct_minima = static_cast<int>(optima.size());
  result.best =
      *std::min_element(optima.begin(), optima.end(),
                        [](const Optimum& a, const Optimum& b) { return a.value < b.value; });
  return result;
}

}  // namespace hecal::estimation::internal
