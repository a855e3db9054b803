// `hecal poses convert` (docs/cli.md#hecal-poses-convert): the flags fill
// io::PoseConversionOptions; the job is io::ConvertPoseTable (io/pose_conversion.h); this file
// writes its result atomically and prints the summary.
#pragma once

#include <string>

#include "cli.h"

namespace hecal::cli {

struct PosesConvertOptions {
  std::string input;
  std::string output;
  std::string to;        // quaternion | rotvec | matrix | euler:SEQ | rpy | kuka | fanuc | abb | ur
  std::string units;     // "m" | "mm" | "" (= the input's unit)
  bool degrees = false;  // output angles in degrees
  bool invert = false;   // write T⁻¹ for every pose
  std::string input_units;  // "m" | "mm" | "" (= m); header suffixes win
  bool input_degrees = false;
  std::string euler;  // sequence of a1,a2,a3 input columns, "" = none
};

// Runs the conversion; throws hecal::InputError for bad flags or input.
void RunPosesConvert(const PosesConvertOptions& options, const Io& io);

}  // namespace hecal::cli
