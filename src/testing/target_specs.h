// Test support (not installed): targets the tests of several layers build (pose/target.h's
// TargetSpec; the rendered scenes of testing/rendered_scene.h use them too).
#pragma once

#include "hecal/pose/target.h"

namespace hecal::testing {

// A chessboard of cols × rows inner corners, `square` metres apart (pose/target.h).
inline pose::TargetSpec Chessboard(int cols, int rows, double square) {
  return {.type = pose::TargetType::kChessboard, .cols = cols, .rows = rows, .square = square};
}

// 5 × 4 tag36h11 AprilTags with ids 3 to 22, 40 mm markers 12 mm apart (pose/target.h).
inline pose::TargetSpec AprilTagGrid() {
  return {.type = pose::TargetType::kAprilTagGrid,
          .cols = 5,
          .rows = 4,
          .marker = 0.04,
          .spacing = 0.012,
          .family = "tag36h11",
          .first_id = 3};
}

}  // namespace hecal::testing
