// The target-free calibration's result as readable text (what `hecal calibrate --method global`
// prints; docs/global.md), beside its result file (global_calibration.h).
//
// Lines: the method and setup; X (eye-in-hand T_gripper_camera, eye-to-hand T_base_camera) as
// its rotation vector in radians and its translation; the 1σ of both (radians, the unit), then the
// 1σ of the translation along X's parent frame's axes (translation_sigma.h); the noise levels —
// the ray's in radians and the robot's per pose (rotation radians, translation the unit), marked
// "robot given, ray estimated" or "estimated"; the certificate — the bracket of the largest ray
// error in radians, certified or not, cubes, LPs and seconds, to 4 significant digits; the
// matches kept and removed, with the L∞ threshold in radians. Vectors and numbers otherwise print
// with the stream's settings (6 significant digits by default). Lengths in `unit` (the robot
// file's length unit; the result holds metres).
#pragma once

#include <ostream>

#include "hecal/io/units.h"
#include "hecal/report/global_result.h"

namespace hecal::report {

void PrintGlobalSummary(std::ostream& out, const GlobalCalibrationResult& result,
                        io::LengthUnit unit);

}  // namespace hecal::report
