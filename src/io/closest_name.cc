#include "closest_name.h"

#include <algorithm>
#include <vector>

#include "hecal/io/delimited_text.h"

namespace hecal::io::internal {
namespace {}  // namespace

size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::string ClosestName(std::string_view name, std::span<const std::string_view> candidates) {
  // Names far longer than any key or dictionary name are not slips; skip the quadratic work.
  constexpr size_t kLongest = 64;
  if (name.size() > kLongest) return "";
  const std::string lower = Lowercase(name);
  const size_t limit = std::max<size_t>(2, name.size() / 4);
  std::string best;
  size_t best_distance = limit + 1;
  for (const std::string_view candidate : candidates) {
    const size_t distance = EditDistance(lower, Lowercase(candidate));
    if (distance < best_distance) {
      best_distance = distance;
      best = std::string(candidate);
    }
  }
  return best;
}

std::string DidYouMean(std::string_view name, std::span<const std::string_view> candidates) {
  const std::string closest = ClosestName(name, candidates);
  return closest.empty() ? std::string() : " (did you mean '" + closest + "'?)";
}

}  // namespace hecal::io::internal
