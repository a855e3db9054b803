// A report's image thumbnail (docs/report.md, "From images"): one image file read as
// vision::ReadGrayImage reads it (bounded, hecal's reasons for a file it refuses), downscaled with
// pixel-area averaging so that its longer side is at most `max_side` pixels (never enlarged),
// and encoded as a JPEG (quality 80) by OpenCV. Grey: what the target detection saw.
// Errors: those of ReadGrayImage (InputError naming the file).
#pragma once

#include <string>

namespace hecal::vision {

// The JPEG file's bytes.
std::string ThumbnailJpeg(const std::string& path, int max_side);

}  // namespace hecal::vision
