// Test support (not installed): the synthetic camera and scene of the image tests, every number
// an option: the camera's intrinsics and plumb_bob distortion (pose/camera_model.h), a planar
// grid target, the stations (testing/scene.h: setup, count, spread, robot noise), Gaussian pixel
// noise and the seed.
//
// MakeImageScene draws, from one std::mt19937_64 seeded with `seed`: first the stations
// (MakeScene: X, Z, the true poses, then the robot noise), then per station and per grid point
// two standard normals (y, then x), scaled by pixel_sigma — drawn also when pixel_sigma is zero, so
// that the noise-free pixels and the stations of a seed do not depend on it. The pixels are the
// projections through the TRUE camera poses (T_camera_target_true) of the grid points, plus
// that noise. Frames and units: testing/scene.h and docs/conventions.md; metres, pixels.
//
// The defaults are a compact scene for a 640×480 camera: the camera 1 m from the target, in a
// 0.4 m cube, tilted up to ±20° with a free spin, looking at a 9 × 6 grid of 30 mm pitch
// centred on the target origin, so that every grid point is in front of every camera and in
// the image.
//
// MakePointView draws one view for the pose-from-known-points methods (pose/*.h), no stations:
// from the caller's generator, first per object point z (a volume only), y, x, uniform in a cube
// of side `side` centred on the target origin (z = 0 for a plane, OpenCV's board frame); then the
// rotation (uniform on SO(3) for a volume; for a plane a heading, a free spin about the normal
// and a tilt in [0, max_tilt] about the in-plane axis at that heading, R = R_tilt · R_spin); then
// y, x of the target origin's lateral offset (uniform in ±lateral; z = distance) in the camera
// frame. The pixels are exact projections; AddPixelNoise draws y then x per pixel from the same
// generator.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"
#include "testing/random_poses.h"
#include "testing/scene.h"

namespace hecal::testing {

// A planar grid in the target frame (z = 0, metres): cols × rows points `pitch` apart,
// row-major (point r·cols + c at column c, row r). The origin at the first point, or at the
// grid's centre when `centred`.
struct GridOptions {
  int cols = 9;
  int rows = 6;
  double pitch = 0.03;
  bool centred = true;
};

inline std::vector<Eigen::Vector3d> GridPoints(const GridOptions& grid) {
  const Eigen::Vector3d origin = grid.centred
                                     ? Eigen::Vector3d(0.5 * grid.pitch * (grid.cols - 1),
                                                       0.5 * grid.pitch * (grid.rows - 1), 0.0)
                                     : Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> points;
  for (int r = 0; r < grid.rows; ++r) {
    for (int c = 0; c < grid.cols; ++c) {
      points.push_back(Eigen::Vector3d(grid.pitch * c, grid.pitch * r, 0.0) - origin);
    }
  }
  return points;
}

// 640 × 480 px, f ≈ 800 px, the principal point a little off-centre, mild radial and
// tangential distortion.
inline pose::CameraModel DefaultCamera() {
  return {800.0, 805.0, 321.0, 238.0, 640, 480, {-0.12, 0.08, 0.0005, -0.0003, 0.0}};
}

// The stations of the default scene (see the header): testing/scene.h's options with a 0.4 m
// cube and ±20° tilt.
inline SceneOptions CompactStations() {
  SceneOptions stations;
  stations.cube_side = 0.4;
  stations.max_tilt = 20.0 * std::numbers::pi / 180.0;
  return stations;
}

struct ImageSceneOptions {
  pose::CameraModel camera = DefaultCamera();  // intrinsics and distortion
  GridOptions grid;                            // the target
  SceneOptions stations = CompactStations();   // setup, count, spread, robot noise
  double pixel_sigma = 0.0;                    // px, isotropic Gaussian per coordinate
  std::uint64_t seed = 1;

  // The default scene with the options a test varies most set.
  static ImageSceneOptions For(handeye::Setup setup, int stations, std::uint64_t seed,
                               const PoseNoise& robot_noise = {}, double pixel_sigma = 0.0) {
    ImageSceneOptions options;
    options.stations.setup = setup;
    options.stations.stations = stations;
    options.stations.robot_noise = robot_noise;
    options.pixel_sigma = pixel_sigma;
    options.seed = seed;
    return options;
  }
};

// One station's image: the grid points (target frame) and their pixels, same order.
struct StationImage {
  std::vector<Eigen::Vector3d> target;
  std::vector<Eigen::Vector2d> pixels;
};

struct ImageScene {
  Scene poses;  // truth and (noisy) robot poses
  pose::CameraModel camera;
  std::vector<StationImage> images;  // one per station

  // The images as another {target, pixels} aggregate (e.g. estimation::ImagePoints).
  template <typename Points>
  std::vector<Points> ImagesAs() const {
    std::vector<Points> out;
    for (const StationImage& image : images) out.push_back(Points{image.target, image.pixels});
    return out;
  }
};

inline ImageScene MakeImageScene(const ImageSceneOptions& options) {
  std::mt19937_64 rng(options.seed);
  ImageScene scene{MakeScene(options.stations, rng), options.camera, {}};
  const std::vector<Eigen::Vector3d> grid = GridPoints(options.grid);
  hecal::NormalDistribution normal(0.0, 1.0);
  for (const Pose& T_camera_target : scene.poses.T_camera_target_true) {
    StationImage image;
    for (const Eigen::Vector3d& P : grid) {
      image.target.push_back(P);
      const double ny = normal(rng);
      const double nx = normal(rng);
      const Eigen::Vector2d n(nx, ny);
      image.pixels.push_back(pose::Project(options.camera, T_camera_target * P) +
                             options.pixel_sigma * n);
    }
    scene.images.push_back(std::move(image));
  }
  return scene;
}

// One view of N known object points (see the header for the draws).
enum class PointShape { kVolume, kPlane };

struct PointViewOptions {
  pose::CameraModel camera = DefaultCamera();
  int points = 10;
  PointShape shape = PointShape::kVolume;
  double side = 0.4;      // m, the cube (or square) holding the points
  double distance = 1.0;  // m, the target origin's depth in the camera frame
  double lateral = 0.1;   // m, the largest x and y offset of the target origin
  double max_tilt = 40.0 * std::numbers::pi / 180.0;  // rad, a plane's tilt from frontal
};

struct PointView {
  pose::CameraModel camera;
  Pose T_camera_target = Pose::Identity();  // the truth
  std::vector<Eigen::Vector3d> object_points;
  std::vector<Eigen::Vector2d> pixels;  // exact projections
};

inline PointView MakePointView(const PointViewOptions& options, std::mt19937_64& rng) {
  hecal::UniformRealDistribution side(-options.side / 2, options.side / 2),
      lateral(-options.lateral, options.lateral), tilt(0.0, options.max_tilt),
      spin(-std::numbers::pi, std::numbers::pi);
  const bool volume = options.shape == PointShape::kVolume;
  PointView view;
  view.camera = options.camera;
  for (int k = 0; k < options.points; ++k) {
    const double z = volume ? side(rng) : 0.0;
    const double y = side(rng);
    const double x = side(rng);
    view.object_points.emplace_back(x, y, z);
  }
  Eigen::Matrix3d R;
  if (volume) {
    R = RandomRotation(rng);
  } else {
    const double heading = spin(rng);
    const Eigen::Vector3d in_plane_axis(std::cos(heading), std::sin(heading), 0.0);
    const double turn = spin(rng);
    const double angle = tilt(rng);
    R = Eigen::AngleAxisd(angle, in_plane_axis).toRotationMatrix() *
        Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }
  const double offset_y = lateral(rng);
  const double offset_x = lateral(rng);
  view.T_camera_target = MakePose(R, Eigen::Vector3d(offset_x, offset_y, options.distance));
  for (const Eigen::Vector3d& P : view.object_points) {
    view.pixels.push_back(pose::Project(options.camera, view.T_camera_target * P));
  }
  return view;
}

// `pixels` plus isotropic Gaussian noise of `sigma` px per coordinate from `rng` (nothing drawn
// when sigma is zero).
inline std::vector<Eigen::Vector2d> AddPixelNoise(std::mt19937_64& rng,
                                                  const std::vector<Eigen::Vector2d>& pixels,
                                                  double sigma) {
  std::vector<Eigen::Vector2d> noisy = pixels;
  if (sigma > 0.0) {
    hecal::NormalDistribution normal(0.0, sigma);
    for (Eigen::Vector2d& u : noisy) {
      const double dy = normal(rng);
      const double dx = normal(rng);
      u += Eigen::Vector2d(dx, dy);
    }
  }
  return noisy;
}

}  // namespace hecal::testing
