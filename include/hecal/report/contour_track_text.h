// A tracked frame as one line of readable text (what `hecal contour track` prints per frame, as
// it is tracked; docs/cli.md#hecal-contour-track), beside the track's CSV and JSON
// (contour_track_file.h).
//
// The line: the frame number (4 wide), the image file (24 wide), the status (tracked | lost |
// singular), the edges used / searched and the measurement σ in px (3 decimals); with a pose, the
// translation T (the unit of Z0) and the three angles of the rotation form (PoseParameterNames,
// degrees), 3 decimals each, and "(bias)" when the bias check flags any parameter. Ends with a
// newline.
#pragma once

#include <string>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/sequence.h"

namespace hecal::report {

std::string ContourTrackLine(const contour::TrackedImage& image, contour::RotationForm form);

}  // namespace hecal::report
