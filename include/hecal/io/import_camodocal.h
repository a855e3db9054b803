// handeye_calib_camodocal transform pairs (TransformPairsInput.yml / TransformPairsOutput.yml)
// → robot and camera pose tables.
//
// Format: OpenCV FileStorage YAML ("%YAML:1.0", "!!opencv-matrix" nodes with rows, cols, dt and
// row-major data) holding `frameCount: N` and, for i = 0..N−1, `T1_i` and `T2_i` (4×4, metres).
//   T1_i = lookupTransform(base, ee)        = T_base_ee       → robot row as is
//   T2_i = lookupTransform(camera, ar_tag)  = T_camera_marker → camera row as is
// Source: data/camodocal-artag/SOURCE.md (handeye_calibration.cpp addFrame() and
// writeTransformPairsToFile()). Ids are the i of T1_i / T2_i. frameCount must equal the number
// of T1_i and of T2_i entries, and the indices must run 0..N−1.
#pragma once

#include <string>
#include <string_view>

#include "hecal/io/import_types.h"

namespace hecal::io {

ImportedPoses ParseCamodocalPairs(std::string_view yaml_text, const std::string& source);

}  // namespace hecal::io
