// Target corners as anonymous matches: see corner_matches.h.
#include "hecal/vision/corner_matches.h"

#include <algorithm>
#include <string>
#include <utility>

#include "hecal/core/error.h"
#include "hecal/pose/camera_model.h"

namespace hecal::vision {

std::vector<CornerMotion> MatchTargetCorners(const ImageSet& set, int per_motion) {
  if (per_motion < 1) {
    throw InputError("target corner matches", 0,
                     "at most " + std::to_string(per_motion) + " matches per motion",
                     "ask for at least one match per motion");
  }
  std::vector<int> used;
  for (std::size_t i = 0; i < set.images.size(); ++i) {
    if (set.images[i].used()) used.push_back(int(i));
  }
  std::vector<CornerMotion> motions;
  for (std::size_t k = 0; k + 1 < used.size(); ++k) {
    const ImageRecord& first = set.images[std::size_t(used[k])];
    const ImageRecord& second = set.images[std::size_t(used[k + 1])];
    // Both point lists are sorted by id.
    std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> common;
    std::vector<int> ids;
    auto a = first.detection.points.begin(), b = second.detection.points.begin();
    while (a != first.detection.points.end() && b != second.detection.points.end()) {
      if (a->id < b->id) {
        ++a;
      } else if (b->id < a->id) {
        ++b;
      } else {
        common.emplace_back(a->pixel, b->pixel);
        ids.push_back(a->id);
        ++a;
        ++b;
      }
    }
    CornerMotion motion;
    motion.first = used[k];
    motion.second = used[k + 1];
    const int n = int(common.size());
    const int take = std::min(n, per_motion);
    for (int j = 0; j < take; ++j) {
      const std::size_t index = std::size_t((long(j) * n) / take);
      motion.ids.push_back(ids[index]);
      motion.first_rays.push_back(pose::PixelRay(set.camera, common[index].first, first.name, 0));
      motion.second_rays.push_back(
          pose::PixelRay(set.camera, common[index].second, second.name, 0));
    }
    motions.push_back(std::move(motion));
  }
  return motions;
}

}  // namespace hecal::vision
