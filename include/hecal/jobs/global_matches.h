// The point matches of the target-free calibration from a folder of station images, as one job
// (`hecal calibrate --method global --images DIR`; docs/global.md): the robot pose of every
// station and the matched rays of every motion, ready for jobs::CalibrateGlobal
// (jobs/global_calibration.h), printing nothing (texts through JobCallbacks, job_callbacks.h).
//
// Steps (GlobalMatchesFromImages)
//   1. The options checked (IsValid) before any file is read; the robot table read
//      (io/pose_table.h, options.robot_read).
//   2. By options.source:
//      kTargetCorners  the image front end on the folder with the target and the given
//                      intrinsics (image_front_end.h: DetectImages, its texts in that order),
//                      the robot rows paired with its images (RobotPosePerImage, notes), and
//                      the corners of one id in two consecutive used images as one match
//                      (vision/corner_matches.h: at most matches_per_motion per motion, spread
//                      over the target; the motions name the images' stations);
//      kSift, kOrb     the station images listed (io/image_files.h), the robot rows paired with
//                      them (io/image_pairing.h, notes), generic features matched between
//                      consecutive images (vision/feature_matches.h: ratio test, RANSAC on the
//                      essential matrix with pixel_sigma's threshold, at most matches_per_motion
//                      spread over the image), then one progress line
//                      "features: N images, M motions, SIFT matches per motion: n1 n2 …" (ORB
//                      for kOrb).
//   3. focal = (fx + fy) / 2 of the intrinsics, which turns jobs::CalibrateGlobal's pixel σ
//      into radians of ray.
// Frames and units: T_base_gripper from the robot table in metres; rays are unit vectors in the
// camera frame of each image of a motion (v in the first, u in the second: global::BearingPair).
//
// Errors (hecal::InputError): invalid options (source the field: GlobalImageMatchOptions.*,
// PoseReadOptions.*, ImageSetOptions.*, FeatureMatchOptions.*); those of the robot table, the
// image front end, the listing, the pairing and the matchers (an unreadable image, too few
// matches in a pair) pass through. Nothing is written.
#pragma once

#include <string>

#include "hecal/io/pose_table.h"
#include "hecal/jobs/job_callbacks.h"
#include "hecal/jobs/global_calibration.h"

namespace hecal::jobs {

// What is matched between the images of two stations.
enum class MatchSource {
  kTargetCorners,  // the corners of a known target (options.target), matched by id
  kSift,           // generic SIFT features (no target)
  kOrb,            // generic ORB features (no target)
};

struct GlobalImageMatchOptions {
  std::string robot;               // the robot pose table: T_base_gripper, one row per image
  io::PoseReadOptions robot_read;  // its units, angles; invert on reading
  std::string images;              // the folder of station images
  std::string target;              // target.yaml: with kTargetCorners only
  std::string intrinsics;          // camera.yaml or ViSP camera XML (io/camera_file.h)
  MatchSource source = MatchSource::kTargetCorners;
  int matches_per_motion = 40;  // the most matches per motion, ≥ 1
  double pixel_sigma = 0.5;     // feature noise per axis, pixels (the RANSAC threshold), > 0
  int threads = 0;              // detection and feature threads; 0 = every core
  std::string caller = "global matches from images";  // names the job in its first progress line

  // core/options_check.h: false naming the first bad field, in the order
  // GlobalImageMatchOptions.robot (empty), robot_read (PoseReadOptions::IsValid), .images,
  // .intrinsics (empty), .target (empty with kTargetCorners), .threads (outside 0 …
  // kMaxThreads), .matches_per_motion (below 1), .pixel_sigma (not positive and finite).
  bool IsValid(std::string* why) const;
};

// Steps 1–3 above; the motions in image order.
GlobalMatches GlobalMatchesFromImages(const GlobalImageMatchOptions& options,
                                              const JobCallbacks& callbacks);

}  // namespace hecal::jobs
