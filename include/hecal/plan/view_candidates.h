// Candidate stations for `hecal plan` (docs/plan.md#how-the-poses-are-chosen): robot poses that
// keep the whole target in view at a usable distance and tilt, inside the workspace, at the
// nominal scene and at every perturbed nominal of the robust design (station_design.h).
//
// Sampling, in the target frame (z into the board, the camera on the −z side):
//  - a viewpoint direction uniform in the cap of half-angle max_board_tilt about −z (the angle
//    between the line of sight and the board's normal), distance U(0.8, 1.2)·distance from the
//    board's centre;
//  - the optical axis at an aim point U(±0.25)·board extent about the centre (so the board moves
//    about the image), the spin about it uniform in (−π, π];
//  - the robot pose from Z = A X B (sim::RobotPoseFor with the nominal X, Z).
// A sample is kept when, for the nominal and for every perturbed nominal, every target point
// projects in front of the camera and inside the image with a margin (margin_fraction of the
// width), and the flange pose is inside the workspace (io::Workspace::Contains).
#pragma once

#include <random>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "hecal/io/workspace_file.h"
#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"

namespace hecal::plan {

struct ViewOptions {
  double distance = 0.0;                     // metres; 0: the board fills half the image width
  double max_board_tilt = 0.7853981633974483;  // radians (45°)
  double margin_fraction = 0.05;             // of the image width, on every side
  int candidates = 600;                      // kept samples wanted
  int max_samples = 60000;                   // samples drawn at most
};

// A nominal scene: X and Z of problem.h for the setup.
struct Scene {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
};

struct ViewCandidate {
  Pose T_base_gripper = Pose::Identity();
  Pose T_camera_target = Pose::Identity();  // at the nominal scene
};

// The default distance: the target's largest extent fills half the image width.
double DefaultDistance(const pose::CameraModel& camera, const std::vector<pose::ObjectPoint>& target);

// True when every point projects in front of `camera` and inside its image with the margin.
bool TargetInView(const pose::CameraModel& camera, const std::vector<pose::ObjectPoint>& target,
                  const Pose& T_camera_target, double margin_pixels);

// The candidates (fewer when the samples run out); `scenes` are the nominal and the perturbed
// nominals a candidate must see the target at; *samples (when given): the poses drawn.
std::vector<ViewCandidate> ViewCandidates(const std::vector<Scene>& scenes,
                                          const pose::CameraModel& camera,
                                          const std::vector<pose::ObjectPoint>& target,
                                          const io::Workspace& workspace,
                                          const ViewOptions& options, std::mt19937_64& rng,
                                          int* samples = nullptr);

}  // namespace hecal::plan
