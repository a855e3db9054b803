// The image front end as the jobs of this layer run it (`hecal detect`, `hecal calibrate
// --images`, `hecal calibrate --method global` from target images): vision::DetectImageSet
// (vision/image_set.h) with its stages handed out as they finish (job_callbacks.h), and the
// robot rows paired with its images (io/image_pairing.h).
//
// The order of the texts (docs/cli.md#hecal-detect):
//   1. the folder listed: the listing note (sub-folders hidden by top-level images), if any, then
//      the progress line of image_set_text.h;
//   2. when detection left fewer usable images than the use needs: the per-image table, before
//      DetectImageSet refuses the set;
//   3. the intrinsics text, then (estimated) one warning "intrinsics: …" per warning of the
//      estimate;
//   4. the per-image table;
//   5. the fit warning of given intrinsics (ImageSet::fit_warning), which DetectImageSet sets
//      after its last stage: handed out when it returns, so before anything a caller does next
//      (such as pairing the robot rows, whose notes follow it).
//
// Errors: those of vision::DetectImageSet and io::PairRobotWithStations pass through.
#pragma once

#include <string>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/io/pose_table.h"
#include "hecal/jobs/job_callbacks.h"
#include "hecal/vision/image_set.h"

namespace hecal::jobs {

// Steps 1–5 above; `caller` names the job in the first line ("hecal detect").
vision::ImageSet DetectImages(const vision::ImageSetOptions& options, const std::string& caller,
                              const JobCallbacks& callbacks);

// One robot pose T_base_gripper per image of `set`, in its order (io::PairRobotWithStations, by
// id or by order); its notes go to callbacks.note. `images_dir` names the folder in messages.
std::vector<Pose> RobotPosePerImage(const io::PoseTable& robot, const vision::ImageSet& set,
                                    const std::string& images_dir, const JobCallbacks& callbacks);

}  // namespace hecal::jobs
