// Target corners as anonymous point matches for the target-free calibration (docs/global.md,
// "Target corners as matches"): the corners the detector found in the images of two consecutive
// usable stations of an ImageSet (image_set.h; images sorted by name) that carry the same id
// are one match of that motion. Only the ids and the pixels are used; the target's size and
// square never enter. At most `per_motion` matches per motion, evenly spaced in id order
// (spread over the target): match j of the n common corners is the one at index ⌊j n / take⌋,
// take = min(n, per_motion).
// Rays: unit vectors in each camera's frame through the undistorted pixel (pose::PixelRay).
// Errors: InputError naming the image when a corner cannot be undistorted, and when per_motion
// is below 1.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "hecal/vision/image_set.h"

namespace hecal::vision {

struct CornerMotion {
  int first = 0;                            // index into ImageSet::images
  int second = 0;                           // the next used image
  std::vector<int> ids;                     // corner ids, ascending
  std::vector<Eigen::Vector3d> first_rays;  // one per id, first camera frame
  std::vector<Eigen::Vector3d> second_rays;
};

// One motion per pair of consecutive used images, in order.
std::vector<CornerMotion> MatchTargetCorners(const ImageSet& set, int per_motion);

}  // namespace hecal::vision
