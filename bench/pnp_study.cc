// Accuracy study of pose from known points (docs/pose-from-points.md): the linear pose paper alone
// (linear-raw), the linear pose paper + reprojection refinement (linear), the normalised DLT /
// homography + refinement (dlt), and OpenCV 4.6's solvePnP methods as peers (ITERATIVE, EPNP,
// SQPNP; IPPE on planar targets), on identical synthetic data: for each cell (shape, N, pixel σ)
// the same scenes and the same noisy pixels go to every method.
//
// Scenes (src/testing/pose_scenes.h): a 1280×960 camera, f ≈ 1000 px, mild plumb_bob distortion;
// N points uniform in a 0.4 m cube 1 m away (uniformly random orientation), or on a 0.4 m square
// tilted up to 40°. Pixel noise: isotropic Gaussian σ ∈ {0, 0.1, 0.5, 1, 2} px. N ∈ {6, 10, 20,
// 50}. Errors: rotation angle of R̂ᵀR (deg) and ‖t̂ − t‖ (mm), RMSE over the trials (default 200,
// or argv[1]); a method that throws on a trial counts as a failure (reported, not in the RMSE).
// Also the mean time per solve (µs, this machine, single thread).
//
// Prints a Markdown table per shape. Build with -DHECAL_BUILD_BENCH=ON; run bin/pnp_study [trials].
#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/pose/pose_method.h"
#include "testing/pose_scenes.h"
#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "hecal/vision/opencv_pnp.h"
#endif

namespace {

using hecal::Pose;
using hecal::testing::PointShape;
using hecal::testing::PointView;

using Solver = std::function<Pose(const PointView&, const std::vector<Eigen::Vector2d>&)>;

struct Method {
  std::string name;
  Solver solve;
  bool planar;      // accepts coplanar points
  bool non_planar;  // accepts points in a volume
};

std::vector<Method> Methods() {
  using hecal::pose::PoseMethod;
  const auto hecal_method = [](PoseMethod method) {
    return [method](const PointView& scene, const std::vector<Eigen::Vector2d>& pixels) {
      return hecal::pose::EstimatePose(method, scene.object_points, pixels, scene.camera)
          .T_camera_target;
    };
  };
  std::vector<Method> methods = {
      {"linear-raw", hecal_method(PoseMethod::kLinearRaw), false, true},
      {"linear", hecal_method(PoseMethod::kLinear), false, true},
      {"dlt", hecal_method(PoseMethod::kDlt), true, true},
  };
#if defined(HECAL_HAVE_OPENCV_PEERS)
  for (const hecal::vision::PnpMethodInfo& info : hecal::vision::OpenCvPnpMethods()) {
    const hecal::vision::PnpMethod method = info.method;
    methods.push_back(
        {"cv-" + std::string(info.name),
         [method](const PointView& scene, const std::vector<Eigen::Vector2d>& pixels) {
           return hecal::vision::SolvePnPOpenCv(method, scene.object_points, pixels, scene.camera);
         },
         true, !info.planar_only});
  }
#endif
  return methods;
}

struct Cell {
  double rotation_sq = 0.0;     // Σ deg²
  double translation_sq = 0.0;  // Σ mm²
  double seconds = 0.0;
  int solved = 0;
  int failed = 0;
};

void RunShape(PointShape shape, int trials, const std::vector<Method>& methods) {
  const bool planar = shape == PointShape::kPlane;
  std::vector<const Method*> used;
  for (const Method& m : methods) {
    if (planar ? m.planar : m.non_planar) used.push_back(&m);
  }
  std::printf("\n%s target: rotation RMSE (deg) / translation RMSE (mm) over %d trials\n\n",
              planar ? "Planar (0.4 m square, tilt <= 40 deg)" : "Non-coplanar (0.4 m cube)",
              trials);
  std::printf("| N | sigma px |");
  for (const Method* m : used) std::printf(" %s |", m->name.c_str());
  std::printf("\n|---|---|");
  for (std::size_t i = 0; i < used.size(); ++i) std::printf("---|");
  std::printf("\n");

  std::vector<Cell> timing(used.size());
  for (int n : {6, 10, 20, 50}) {
    for (double sigma : {0.0, 0.1, 0.5, 1.0, 2.0}) {
      std::mt19937_64 rng(1000u * static_cast<unsigned>(n) + static_cast<unsigned>(10 * sigma) +
                          (planar ? 7u : 0u));
      std::vector<Cell> cells(used.size());
      for (int trial = 0; trial < trials; ++trial) {
        const PointView scene = hecal::testing::RandomScene(rng, n, shape);
        const std::vector<Eigen::Vector2d> pixels =
            hecal::testing::AddPixelNoise(rng, scene.pixels, sigma);
        for (std::size_t i = 0; i < used.size(); ++i) {
          const auto start = std::chrono::steady_clock::now();
          try {
            const Pose T = used[i]->solve(scene, pixels);
            cells[i].seconds +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const double rotation =
                Eigen::AngleAxisd(T.linear().transpose() * scene.T_camera_target.linear()).angle() *
                180.0 / std::numbers::pi;
            const double translation =
                1000.0 * (T.translation() - scene.T_camera_target.translation()).norm();
            if (!std::isfinite(rotation) || !std::isfinite(translation)) {
              throw std::runtime_error("non-finite pose");
            }
            cells[i].rotation_sq += rotation * rotation;
            cells[i].translation_sq += translation * translation;
            ++cells[i].solved;
          } catch (const std::exception&) {
            ++cells[i].failed;
          }
        }
      }
      std::printf("| %d | %g |", n, sigma);
      for (std::size_t i = 0; i < used.size(); ++i) {
        const Cell& c = cells[i];
        if (c.solved == 0) {
          std::printf(" fails |");
          continue;
        }
        std::printf(" %.3g / %.3g%s |", std::sqrt(c.rotation_sq / c.solved),
                    std::sqrt(c.translation_sq / c.solved),
                    c.failed > 0 ? (" (" + std::to_string(c.failed) + " failed)").c_str() : "");
        timing[i].seconds += c.seconds;
        timing[i].solved += c.solved;
      }
      std::printf("\n");
    }
  }
  std::printf("\nMean time per solve (us):");
  for (std::size_t i = 0; i < used.size(); ++i) {
    std::printf(" %s %.1f%s", used[i]->name.c_str(),
                1e6 * timing[i].seconds / std::max(timing[i].solved, 1),
                i + 1 < used.size() ? "," : "\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int trials = argc > 1 ? std::stoi(argv[1]) : 200;
  if (trials < 1) {
    std::fprintf(stderr, "usage: pnp_study [trials >= 1]\n");
    return 2;
  }
  const std::vector<Method> methods = Methods();
  RunShape(PointShape::kVolume, trials, methods);
  RunShape(PointShape::kPlane, trials, methods);
  return 0;
}
