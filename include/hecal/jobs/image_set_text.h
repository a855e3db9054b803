// The image front end's stages as readable text (vision/image_set.h: what `hecal detect` and
// `hecal calibrate --images` print as each stage finishes; docs/cli.md#hecal-detect). Lengths in
// the per-image table are millimetres and angles degrees whatever the units of the job.
//
//   listed      "CALLER: N image(s) in DIR, target DESCRIPTION (P points)" — "station
//               sub-folder(s)" instead of "image(s)" for one sub-folder per station.
//   intrinsics  given: "intrinsics: FILE (fx …, fy …, cx …, cy … px)" (six significant digits),
//               then "note: …" per note of the camera file. Estimated: the view count, RMS,
//               coverage and normal spread, then fx, fy, cx, cy ± 1σ (3 decimals) and k1 k2 p1 p2
//               k3 ± 1σ (6 decimals); the estimate's own warnings are not part of the text
//               (IntrinsicsResult::warnings: the caller hands them out as warnings).
//   table       one row per image: name, detection status, points found / points of the target,
//               sharpness (px); for an image whose pose was refined its reprojection RMS (px) and
//               the pose's 1σ as the RMS over the three axes of the translation (mm) and of the
//               rotation (deg); for a skipped image "skipped: REASON". Left-aligned columns, the
//               first as wide as the longest name (at least "image").
// Every text ends in '\n'.
#pragma once

#include <string>
#include <vector>

#include "hecal/vision/image_set.h"

namespace hecal::jobs {

// `caller` names the job in its first line ("hecal detect").
std::string ImageSetListedText(const vision::ImageSet& set, const vision::ImageSetOptions& options,
                               const std::string& caller);

// The intrinsics used by `set`: options.intrinsics when given, else set.estimated.
std::string ImageSetIntrinsicsText(const vision::ImageSet& set,
                                   const vision::ImageSetOptions& options);

std::string ImageTableText(const std::vector<vision::ImageRecord>& images);

}  // namespace hecal::jobs
