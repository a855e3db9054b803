// `hecal detect --images DIR --target target.yaml [--intrinsics camera.yaml] --output camera.csv
//               [--threads N]`                                              (docs/cli.md,
//               docs/targets.md)
// Camera poses T_camera_target from images of a calibration target, for `hecal calibrate`.
//
// Steps 1–5 (images, detection, intrinsics, poses, per-image report) are the image front end of
// vision/image_set.h, shared with `hecal calibrate --images`. With --intrinsics one usable image is
// enough (a pose needs no more); without, 3 (estimating the intrinsics needs them). Then
//   6. Files (metres, written only when everything succeeded, all or none: io/atomic_file.h):
//      <output>                  pose table (io/pose_table.h): id (= the station: the image's
//                                file stem, or its sub-folder's name),
//                                x,y,z,qw,qx,qy,qz of T_camera_target, '#' lines saying how
//      <output stem>.points.csv  id,point_id,u,v (io/detection_output.h): the detected pixels of
//                                every used image (point_id = the pose::ObjectPoints id)
//      <output stem>.camera.yaml only when the intrinsics were estimated
//   The output stem is <output> without its extension (camera.csv → camera).
//
// Errors (hecal::InputError, exit 2, nothing written): those of vision/image_set.h (with
// --threads outside 0 … 256: ImageSetOptions::IsValid, checked before anything else), and any of
// the three output paths refused by io::CheckOutputs (checked before the detection): in a directory
// that does not exist, a folder, a device or a FIFO, or one of the inputs (--target, --intrinsics).
#pragma once

#include <string>

#include "cli.h"

namespace hecal::cli {

struct DetectFlags {
  std::string images;
  std::string target;
  std::string intrinsics;  // "" = estimate from the images
  std::string output;
  int threads = 0;  // 0 = every core (vision::ImageSetOptions::IsValid: 0 … 256)
};

// Runs the command; throws hecal::InputError for bad flags or data.
void RunDetect(const DetectFlags& flags, const Io& io);

}  // namespace hecal::cli
