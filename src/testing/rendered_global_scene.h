// Test support (not installed) for the tests of `hecal calibrate --method global --target none` on
// rendered textured scenes (testing/textured_stations.h): writes a scene's files into a folder,
// runs the user's command on them through the caller's runner (the CLI tests run hecal
// in-process) and reads the result file against the truth. The error is the right perturbation δ =
// Log(X̂⁻¹ X) (geometry/se3.h; rotation first, radians and metres), read with the result's own
// covariance (covariance.X, the same perturbation): NEES = δᵀ C⁻¹ δ, χ²₆ when the covariance holds.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "hecal/geometry/se3.h"
#include "hecal/io/atomic_file.h"
#include "testing/textured_stations.h"

namespace hecal::testing {

struct RenderedGlobalOutcome {
  int code = 0;                    // hecal's exit code
  std::string err;                 // its stderr
  double rotation_error = 0.0;     // radians, |ω| of δ
  double translation_error = 0.0;  // metres, |t̂ − t|
  double rotation_sigma = 0.0;     // radians, RMS of the three rotation σ
  double translation_sigma = 0.0;  // metres, RMS of the three translation σ
  double nees = 0.0;
  Vector6d z = Vector6d::Zero();  // δ per axis over its σ
  int inliers = 0;
  int removed = 0;
  bool certified = false;
};

// `flags` are added to: calibrate --images DIR/images --target none --intrinsics DIR/camera.yaml
// --robot DIR/robot.csv --setup eye-in-hand --method global --output DIR/out.json; `run(args)`
// runs hecal with them (no program name) and returns its exit code and standard error as the
// members `code` and `err`.
template <typename Run>
RenderedGlobalOutcome CalibrateRenderedScene(const TexturedStationSpec& spec, std::uint64_t seed,
                                             const std::filesystem::path& dir,
                                             const std::vector<std::string>& flags, Run&& run) {
  const TexturedStations scene = MakeTexturedStations(spec, seed);
  WriteStationFiles(scene, spec.rendering, seed, dir);
  std::vector<std::string> args = {"calibrate",
                                   "--images",
                                   (dir / "images").string(),
                                   "--target",
                                   "none",
                                   "--intrinsics",
                                   (dir / "camera.yaml").string(),
                                   "--robot",
                                   (dir / "robot.csv").string(),
                                   "--setup",
                                   "eye-in-hand",
                                   "--method",
                                   "global",
                                   "--output",
                                   (dir / "out.json").string()};
  args.insert(args.end(), flags.begin(), flags.end());
  const auto ran = std::forward<Run>(run)(args);
  RenderedGlobalOutcome outcome;
  outcome.code = ran.code;
  outcome.err = ran.err;
  if (ran.code != 0) return outcome;
  const nlohmann::json result = nlohmann::json::parse(io::ReadFile((dir / "out.json").string()));
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  Matrix6d C;
  for (int r = 0; r < 3; ++r) {
    t(r) = result["X"]["translation_m"][r].get<double>();
    for (int c = 0; c < 3; ++c) R(r, c) = result["X"]["rotation"][r][c].get<double>();
  }
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) C(r, c) = result["covariance"]["X"][r][c].get<double>();
  }
  const Vector6d delta = se3::Log(MakePose(R, t).inverse() * scene.X);
  outcome.rotation_error = delta.head<3>().norm();
  outcome.translation_error = (t - scene.X.translation()).norm();
  outcome.rotation_sigma = std::sqrt(C.diagonal().head<3>().mean());
  outcome.translation_sigma = std::sqrt(C.diagonal().tail<3>().mean());
  outcome.nees = delta.dot(C.inverse() * delta);
  outcome.z = delta.cwiseQuotient(C.diagonal().cwiseSqrt());
  outcome.inliers = result["matches"]["inliers"].get<int>();
  outcome.removed = int(result["matches"]["removed"].size());
  outcome.certified = result["certificate"]["certified"].get<bool>();
  return outcome;
}

}  // namespace hecal::testing
