// Synthetic pivot calibrations with ground truth (docs/pivot.md#the-study): a tool tip held at
// one point while the flange takes random orientations, for estimation/pivot.h's tests and the
// study of `hecal simulate --pivot`.
//
// Scene (metres, radians): the tip offset t_tip = (N(0, 0.02²), N(0, 0.02²), U(0.1, 0.25)) in the
// flange frame (a tool along the flange's z axis, slightly off-centre); the pivot point p
// uniform in [0.4, 0.8] × [−0.3, 0.3] × [0, 0.3] in the base frame; orientation i
// R_i = Rx(π) · Exp(ω_i), ω_i uniform in [−max_tilt, max_tilt]³ (flange z pointing down, tilted
// and spun about the flange's axes), t_i = p − R_i t_tip (P1 of estimation/pivot.h). The robot
// reports T̃_i = T_i · Exp(δ_i) with sim::AddNoise (Gaussian right perturbation, σ per axis).
#pragma once

#include <random>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/sim/noise.h"

namespace hecal::sim {

struct PivotScene {
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();    // flange frame
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();  // base frame
  std::vector<Pose> exact;                          // T_base_flange_i without noise
  std::vector<Pose> T_base_flange;                  // as the robot reports them
};

struct PivotSceneOptions {
  int stations = 20;
  double max_tilt = 0.5235987755982988;  // radians per axis (30°)
  double rotation_sigma = 0.0;           // radians per axis
  double translation_sigma = 0.0;        // metres per axis
};

PivotScene SimulatePivot(const PivotSceneOptions& options, std::mt19937_64& rng);

}  // namespace hecal::sim
