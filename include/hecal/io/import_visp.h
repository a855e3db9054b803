// ViSP hand–eye pose files (one vpPoseVector YAML file per station and side) → robot and camera
// pose tables.
//
// Format: what vpArray2D::saveYAML (ViSP modules/core/include/visp3/core/vpArray2D.h) writes for
// a vpPoseVector, a 6×1 array [tx, ty, tz, θux, θuy, θuz]:
//
//   rows: 6
//   cols: 1
//   data:
//     - [0.335091]
//     - [-0.0321497]
//     - [0.30857]
//     - [-3.01226]
//     - [0.0236777]
//     - [-0.451343]
//
// t in metres; θu is the rotation vector (axis times angle, radians; vpRotationMatrix::buildFrom(
// vpThetaUVector) is Rodrigues' formula), of any magnitude. saveYAML prints with the stream's
// default precision, 6 significant digits. Keys other than rows, cols and data (saveYAML's
// optional header lines) are ignored, as vpArray2D::loadYAML ignores them. rows and cols must be
// 6 and 1, and data six one-number rows.
//
// File names give the side and the station: <prefix>pose_<side>_<i>.yaml (or .yml), <i> a
// non-negative whole number, <prefix> anything (ViSP's apps write "franka_", "ur_" or nothing):
//   rPe  rMe = T_base_gripper: vpRobot::getPosition(vpRobot::END_EFFECTOR_FRAME) saved by
//        apps/calibration/hand-eye/visp-acquire-{franka,universal-robots}-calib-data.cpp,
//        read by visp-compute-eye-{in,to}-hand-calibration.cpp as rMe        → robot row as is
//   fPe  the same pose under its name before ViSP 3.7 (fixed frame f = robot base)
//                                                                             → robot row as is
//   cPo  cMo = T_camera_target: vpPose / vpDetectorAprilTag's cMo saved by
//        visp-compute-{chessboard,apriltag}-poses.cpp                         → camera row as is
// The files are the same for eye-in-hand and eye-to-hand (ViSP's eye-to-hand app inverts cMo in
// memory). Robot and camera files pair by <i>, in numeric order; the station id is <i> (without
// leading zeros). Errors (hecal::InputError): an index with a robot file and no camera file or
// the reverse (naming the file and the partner it lacks), two robot files (fPe and rPe, or two
// prefixes) or two camera files for one index, a name that is not a ViSP pose file name (for
// files given explicitly), no pose files at all, and in a file: bad YAML, rows/cols other than
// 6×1, a data length that disagrees with them, non-numbers, NaN/Inf.
#pragma once

#include <string>
#include <vector>

#include "hecal/io/import_types.h"

namespace hecal::io {

// One pose file: its path (the name gives side and index) and its text.
struct VispPoseFile {
  std::string path;
  std::string text;
};

// The pose files named by `inputs`: a directory contributes every file in it whose name is a
// ViSP pose file name (others, such as images and camera XML, are skipped); a path with '*', '?'
// or '[' in its file name is a glob pattern (fnmatch) over its directory, and every match must be
// a pose file; any other path is one pose file. The same file named twice counts once. Sorted by
// path. Throws InputError for a missing file or directory, a pattern without matches or with
// wildcards in its directory part, and when nothing is found.
std::vector<std::string> ListVispPoseFiles(const std::vector<std::string>& inputs);

// Reads and pairs the files (see above).
ImportedPoses ParseVispPoseFiles(const std::vector<VispPoseFile>& files);

}  // namespace hecal::io
