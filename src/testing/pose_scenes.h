// Test and benchmark support (not installed): the single-view scenes of the pose-from-known-points
// tests (pose/*.h) as option values of testing/image_scene.h's MakePointView. A 1280×960 camera
// (f ≈ 1000 px, mild plumb_bob distortion) looks at an object 1 m away: N points uniform in a
// 0.4 m cube, or on a 0.4 m square (z = 0 in the target frame) tilted up to 40° from
// fronto-parallel, the object's centre up to 0.1 m off the optical axis (a corner of a turned
// cube may project a little outside the frame; the model is defined there too).
#pragma once

#include <random>

#include "hecal/pose/camera_model.h"
#include "testing/image_scene.h"

namespace hecal::testing {

inline pose::CameraModel SceneCamera() {
  return {1000.0, 995.0, 641.5, 478.0, 1280, 960, {-0.08, 0.05, 4e-4, -3e-4, 0.0}};
}

// `points` object points of `shape` seen by `camera`, drawn from `rng` (image_scene.h's
// defaults for the cube, distance, offset and tilt).
inline PointView RandomScene(std::mt19937_64& rng, int points, PointShape shape,
                             const pose::CameraModel& camera = SceneCamera()) {
  return MakePointView({.camera = camera, .points = points, .shape = shape}, rng);
}

}  // namespace hecal::testing
