// The planning study (docs/plan.md#does-it-help): planned stations against the thesis protocol's
// random stations (sim/thesis_protocol.h), on the same simulated scenes.
//
// Each trial draws a truth (X, Z) as the protocol does, and a pool of `pool` stations from the
// protocol's distribution (camera in a 1 m cube 1 m from the target, tilts ±45°, free spin).
//  - random: the first N of the pool, as the protocol takes them;
//  - planned: N of the pool chosen D-optimally for X (plan/station_design.h) at a nominal whose X
//    is the truth's moved by the nominal error (5°, 20 mm along a random direction), robust over
//    the nominal's copies moved once more either way, as `hecal plan` is.
// With `existing` > 0 (the `--next` case): both arms start from the pool's first `existing`
// stations; random adds the next N of the pool, planned chooses N of the rest on top of them.
// Both get the same noise model, are calibrated with ml (noise given, no outlier rejection or
// model check), and compared with the truth. The predicted RMSE is the first-order bound at the
// truth for the stations taken (estimation/bound.h), the RMS over the trials.
#pragma once

#include <cstdint>

#include "hecal/estimation/pose_sigma.h"
#include "hecal/handeye/problem.h"

namespace hecal::jobs {

struct PlanStudyOptions {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  int stations = 10;  // planned (or random) stations
  int existing = 0;   // --next: random stations both arms start from (the first of the pool)
  int trials = 200;
  int pool = 300;
  estimation::PoseSigma robot_sigma{0.05 * 0.017453292519943295, 0.1e-3};
  estimation::PoseSigma camera_sigma{0.1 * 0.017453292519943295, 0.5e-3};
  double nominal_rotation_error = 0.08726646259971647;  // radians (5°)
  double nominal_translation_error = 0.02;              // metres
  std::uint64_t seed = 1;
};

// RMS over the trials, radians and metres.
struct PlanStudyArm {
  double predicted_rotation = 0.0;
  double predicted_translation = 0.0;
  double achieved_rotation = 0.0;
  double achieved_translation = 0.0;
};

struct PlanStudyRow {
  PlanStudyArm random;
  PlanStudyArm planned;
};

PlanStudyRow RunPlanStudy(const PlanStudyOptions& options);

}  // namespace hecal::jobs
