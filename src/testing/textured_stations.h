// Test support (not installed): eye-in-hand station sets looking at rendered textured scenes, for
// the target-free method on images (`hecal calibrate --method global --images DIR --target none`;
// docs/global.md, "Measured"). Written as the user's files: the station PNGs, the robot file and
// the camera file.
//
// Frames and units: metres, radians unless a name says degrees. The world frame is the robot's
// base and the nominal camera frame (z forward, x right, y down). X = T_gripper_camera (fixed,
// StationX()). Station k's camera sits at c_k, turned from the nominal frame by Exp(a_k); its robot
// pose is T_base_gripper_k = T_base_camera_k · X⁻¹ (exact: no robot noise). Arm-like motions,
// as on a real arm (docs/global.md's arm-like scenes): between consecutive stations the camera
// turns by a uniform 10–18° about a random axis (|a_k| kept within 13°) and moves by 2–5 cm in a
// random direction (|c_k| kept within 6 cm); the gripper's translation is then a few cm as well
// (X's lever arm adds (I − R_B) t_X).
//
// The scenes (testing/textured_planes.h, each rectangle with its own BlobTexture, finest blobs
// 4 mm ≈ 5 px at 0.6 m and f = 800 px):
//   kPlane   one plane facing the nominal camera 0.6 m away, 1.2 × 1.0 m;
//   kCorner  the inside of a box corner of the same extent and mean depth: two walls at 90°
//            meeting in the vertical line x = 0, z = 0.75 m, each at 45° to the view, and a floor
//            0.22 m below the camera (y = 0.22 m): depths 0.4–0.75 m.
//
// The camera: 800 × 600 px, f = 800 px, centred, no distortion (StationCamera()). Rendering
// (CameraLike): 3 × 3 samples per pixel, blur 0.6 px, noise 1 grey level, view k seeded with
// seed · 1000 + k.
//
// Files (WriteStationFiles): <dir>/images/view_00.png …, <dir>/robot.csv (x_m, y_m, z_m,
// qw, qx, qy, qz: one row per image, in the images' order), <dir>/camera.yaml (testing/
// camera_yaml.h). Errors: std::runtime_error when a PNG cannot be written.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/so3.h"
#include "testing/camera_yaml.h"
#include "testing/random_poses.h"
#include "testing/textured_planes.h"

namespace hecal::testing {

enum class SceneShape { kPlane, kCorner };

inline pose::CameraModel StationCamera() {
  return {800.0, 800.0, 399.5, 299.5, 800, 600, {0.0, 0.0, 0.0, 0.0, 0.0}};
}

// T_gripper_camera: the camera looks along the gripper's x axis, 10 cm out and a few cm aside.
inline Pose StationX() {
  return MakePose(so3::Exp(Eigen::Vector3d(0.3, -0.2, 1.4)), Eigen::Vector3d(0.04, -0.06, 0.10));
}

inline PlaneRenderOptions CameraLike() {
  PlaneRenderOptions options;
  options.supersampling = 3;
  options.blur_sigma = 0.6;
  options.noise_sigma = 1.0;
  return options;
}

struct TexturedStationSpec {
  SceneShape shape = SceneShape::kPlane;
  int stations = 10;
  pose::CameraModel camera = StationCamera();
  Pose X = StationX();
  PlaneRenderOptions rendering = CameraLike();  // its seed is replaced per view
};

struct TexturedStations {
  std::vector<TexturedPlane> planes;  // world frame
  std::vector<Pose> T_base_camera;    // one per station
  std::vector<Pose> T_base_gripper;   // one per station
  pose::CameraModel camera;
  Pose X = Pose::Identity();
};

// A plane of the scene: origin, its in-plane x and y axes (unit, orthogonal), size, texture seed.
inline TexturedPlane ScenePlane(const Eigen::Vector3d& origin, const Eigen::Vector3d& x_axis,
                                const Eigen::Vector3d& y_axis, double width, double height,
                                std::uint64_t seed) {
  Eigen::Matrix3d R;
  R << x_axis, y_axis, x_axis.cross(y_axis);
  return {MakePose(R, origin), width, height, BlobTexture(seed)};
}

inline std::vector<TexturedPlane> ScenePlanes(SceneShape shape, std::uint64_t seed) {
  const Eigen::Vector3d down = Eigen::Vector3d::UnitY();
  if (shape == SceneShape::kPlane) {
    return {ScenePlane({0.0, 0.0, 0.6}, Eigen::Vector3d::UnitX(), down, 1.2, 1.0, seed)};
  }
  const Eigen::Vector3d fold(0.0, 0.0, 0.75);
  const Eigen::Vector3d left = Eigen::Vector3d(-1.0, 0.0, -1.0).normalized();
  const Eigen::Vector3d right = Eigen::Vector3d(1.0, 0.0, -1.0).normalized();
  return {ScenePlane(fold + 0.5 * left, left, down, 1.2, 1.0, seed),
          ScenePlane(fold + 0.5 * right, right, down, 1.2, 1.0, seed + 1),
          ScenePlane({0.0, 0.22, 0.55}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), 1.4,
                     0.9, seed + 2)};
}

inline TexturedStations MakeTexturedStations(const TexturedStationSpec& spec, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  hecal::UniformRealDistribution uniform(0.0, 1.0);
  TexturedStations scene{ScenePlanes(spec.shape, seed), {}, {}, spec.camera, spec.X};
  Eigen::Vector3d a = RandomRotationVector(rng, 5.0 * M_PI / 180.0);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int k = 0; k < spec.stations; ++k) {
    if (k > 0) {
      Eigen::Vector3d next_a = a, next_c = c;
      do {
        const Eigen::Vector3d axis = RandomUnitVector(rng);  // drawn before the step's size
        next_a = a + (10.0 + 8.0 * uniform(rng)) * M_PI / 180.0 * axis;
      } while (next_a.norm() > 13.0 * M_PI / 180.0);
      do {
        const Eigen::Vector3d direction = RandomUnitVector(rng);  // drawn before the length
        next_c = c + (0.02 + 0.03 * uniform(rng)) * direction;
      } while (next_c.norm() > 0.06);
      a = next_a;
      c = next_c;
    }
    scene.T_base_camera.push_back(MakePose(so3::Exp(a), c));
    scene.T_base_gripper.push_back(scene.T_base_camera.back() * spec.X.inverse());
  }
  return scene;
}

// Renders every station (view k's noise seeded with seed · 1000 + k) and writes the files.
inline void WriteStationFiles(const TexturedStations& scene, const PlaneRenderOptions& rendering,
                              std::uint64_t seed, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir / "images");
  std::ofstream robot(dir / "robot.csv");
  robot << "x_m,y_m,z_m,qw,qx,qy,qz\n";
  robot.precision(17);
  for (std::size_t k = 0; k < scene.T_base_camera.size(); ++k) {
    PlaneRenderOptions options = rendering;
    options.seed = seed * 1000 + k;
    GreyImage image = RenderPlanes(scene.planes, scene.camera, scene.T_base_camera[k], options);
    char name[32];
    std::snprintf(name, sizeof name, "view_%02zu.png", k);
    const cv::Mat mat(image.height, image.width, CV_8U, image.pixels.data());
    if (!cv::imwrite((dir / "images" / name).string(), mat)) {
      throw std::runtime_error("cannot write " + (dir / "images" / name).string());
    }
    const Pose& G = scene.T_base_gripper[k];
    const Eigen::Quaterniond q(G.linear());
    robot << G.translation().x() << "," << G.translation().y() << "," << G.translation().z() << ","
          << q.w() << "," << q.x() << "," << q.y() << "," << q.z() << "\n";
  }
  std::ofstream(dir / "camera.yaml") << CameraYaml(scene.camera);
}

}  // namespace hecal::testing
