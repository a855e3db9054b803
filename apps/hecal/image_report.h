// The image front end as the CLI runs it (`hecal detect`, `hecal calibrate --images`): the job
// vision::DetectImageSet (hecal/vision/image_set.h) with its stages printed as they finish.
//
// stdout: "COMMAND: N image(s) in DIR, target TYPE (P points)" once the folder is listed; the
// intrinsics — "intrinsics: FILE (fx, fy, cx, cy px)" and the camera file's notes, or the
// estimate with its 1σ and RMS; then one row per image — file, status (found | partial |
// not_found | ambiguous), points found / points of the target, sharpness (edge width, px;
// smaller is sharper), reprojection RMS at the refined pose (px), the pose's 1σ per axis
// (translation mm, rotation deg: sqrt(trace/3) of each 3×3 block of the covariance) — and for
// skipped images the reason. The table is printed before the intrinsics too when too few images
// are usable, so the error that follows can be read against it.
// stderr: "hecal: note: ..." when top-level images hid station sub-folders, "hecal: warning:
// intrinsics: ..." for a weak estimate, "hecal: warning: FILE: the intrinsics fit the images
// poorly: ..." (vision/intrinsics_fit.h).
// Errors: those of vision::DetectImageSet (hecal::InputError, exit 2).
#pragma once

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <string>

#include "cli.h"
#include "hecal/vision/image_set.h"

namespace hecal::cli {

using vision::ImageRecord;
using vision::ImageSet;
using vision::ImageUse;

// vision::DetectImageSet, printing on `io`; `command` names the caller in the first line
// ("hecal detect").
ImageSet DetectImageSet(const vision::ImageSetOptions& options, const std::string& command,
                        const Io& io);

}  // namespace hecal::cli

#endif  // HECAL_HAVE_OPENCV_PEERS
