// Target corners as anonymous matches, on a hand-made image set whose answer is known: the
// common ids of consecutive used images, thinned evenly, with the rays of a pinhole camera.
#include "hecal/vision/corner_matches.h"

#include <gtest/gtest.h>

#include "hecal/core/error.h"

namespace hecal::vision {
namespace {

ImageRecord Image(const std::string& name, int first_id, int count, const std::string& skipped) {
  ImageRecord image;
  image.name = name;
  image.station = name;
  image.skipped = skipped;
  for (int id = first_id; id < first_id + count; ++id) {
    image.detection.points.push_back({id, Eigen::Vector2d(100.0 + 10.0 * id, 50.0 + id)});
  }
  return image;
}

ImageSet ThreeImages() {
  ImageSet set;
  set.camera.fx = 500.0;
  set.camera.fy = 400.0;
  set.camera.cx = 320.0;
  set.camera.cy = 240.0;
  // The skipped image in the middle is not a station of any motion.
  set.images = {Image("a.png", 0, 10, ""), Image("b.png", 0, 10, "target not found"),
                Image("c.png", 5, 10, "")};
  return set;
}

Eigen::Vector3d Ray(const ImageSet& set, int id) {
  return Eigen::Vector3d((100.0 + 10.0 * id - set.camera.cx) / set.camera.fx,
                         (50.0 + id - set.camera.cy) / set.camera.fy, 1.0)
      .normalized();
}

TEST(MatchTargetCorners, MatchesTheCommonIdsOfConsecutiveUsedImages) {
  const ImageSet set = ThreeImages();
  const std::vector<CornerMotion> motions = MatchTargetCorners(set, 40);
  ASSERT_EQ(motions.size(), 1u);
  EXPECT_EQ(motions[0].first, 0);
  EXPECT_EQ(motions[0].second, 2);
  EXPECT_EQ(motions[0].ids, (std::vector<int>{5, 6, 7, 8, 9}));
  ASSERT_EQ(motions[0].first_rays.size(), 5u);
  ASSERT_EQ(motions[0].second_rays.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_LT((motions[0].first_rays[k] - Ray(set, motions[0].ids[k])).norm(), 1e-15);
    EXPECT_LT((motions[0].second_rays[k] - Ray(set, motions[0].ids[k])).norm(), 1e-15);
  }
}

TEST(MatchTargetCorners, ThinsEvenlyInIdOrder) {
  // 5 common corners, 2 taken: indices 0 and ⌊5/2⌋ = 2.
  EXPECT_EQ(MatchTargetCorners(ThreeImages(), 2)[0].ids, (std::vector<int>{5, 7}));
  EXPECT_THROW(MatchTargetCorners(ThreeImages(), 0), InputError);
}

}  // namespace
}  // namespace hecal::vision
