// `hecal detect` (docs/cli.md#hecal-detect, docs/targets.md): camera poses T_camera_target from
// images of a calibration target, for `hecal calibrate`. The job is jobs::DetectCameraPoses
// (jobs/pose_detection.h: the image front end shared with `hecal calibrate --images`, its stages
// printed by job_output.h); this command checks the output paths first (io::CheckOutputs) and
// writes the pose table, the points file, the estimated intrinsics and, with --report, the detect
// page of the HTML report (jobs/detection_report.h, docs/report.md), all or none.
#pragma once

#include <string>

#include "cli.h"

namespace hecal::cli {

struct DetectFlags {
  std::string images;
  std::string target;
  std::string intrinsics;  // "" = estimate from the images
  std::string output;
  std::string report;  // "" = no page
  int threads = 0;     // 0 = every core (vision::ImageSetOptions::IsValid: 0 … 256)
};

// Runs the command; throws hecal::InputError for bad flags or data.
void RunDetect(const DetectFlags& flags, const Io& io);

}  // namespace hecal::cli
