// What the `hecal import` readers return: the canonical robot and camera pose tables
// (docs/conventions.md) plus the header notes that say where they came from and which conventions
// were applied.
//
//   robot   T_base_gripper_i: the gripper (flange/tool) pose in the robot base frame
//   camera  T_camera_target_i: the target pose in the camera frame (what PnP returns)
//
// Poses are in metres in memory, as everywhere in hecal; each table's `unit` is the length unit
// of the source file and is the unit the CSV is written in (Tabb's millimetres stay millimetres,
// with x_mm,y_mm,z_mm columns). Rows carry an `id` (the source's own name for the sample where it
// has one, else the 0-based sample index) and a `stamp` when the source has time stamps.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/io/pose_table.h"

namespace hecal::io {

// The two hand–eye setups, as some source formats need to know which one recorded them
// (easy_handeye stores the robot transform the other way round for eye-on-base).
enum class ImportSetup { kEyeInHand, kEyeToHand };

// Camera intrinsics found in a source (Tabb's cali.txt), in pixels.
struct ImportedIntrinsics {
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  std::vector<double> distortion;  // plumb_bob: k1, k2, p1, p2, k3
  std::string source;              // file the values came from
};

struct ImportedPoses {
  // T_base_gripper_i. The tables' `warnings` hold the readers' notes (rotation_input.h): one line
  // per source file and kind for rotations that were projected onto SO(3) or normalised.
  PoseTable robot;
  std::optional<PoseTable> camera;  // T_camera_target_i; absent only for robot-only matrix16
  // Header comment lines for robot.csv / camera.csv (without the leading '#').
  std::vector<std::string> robot_notes;
  std::vector<std::string> camera_notes;
  // False when robot and camera rows are separate, unsynchronised streams (ethz): the rows are
  // not stations and must be associated by stamp before calibrating.
  bool synchronised = true;
  // Intrinsics, when the source has one camera model for every image.
  std::optional<ImportedIntrinsics> intrinsics;
  // The files read (ImportFiles), so that a command can refuse to write over one of them.
  std::vector<std::string> sources;
};

// camera.yaml text (docs/targets.md: fx, fy, cx, cy, distortion {model, coefficients}) preceded by
// '#' comment lines. width and height are written only when known (> 0).
std::string FormatIntrinsicsYaml(const ImportedIntrinsics& intrinsics,
                                 const std::vector<std::string>& comments, int width = 0,
                                 int height = 0);

}  // namespace hecal::io
