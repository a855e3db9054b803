// `hecal poses convert` (docs/cli.md): reads a pose table (any rotation group, units from header
// suffixes or flags, or 12/16-number matrix lines), optionally inverts every pose, and writes it
// with the rotation form given by --to. id and stamp columns are kept.
//
// Units:
//   input   header suffixes (x_mm, roll_deg) win; otherwise --input-units (default m) and
//           --input-degrees (default radians; kuka and fanuc columns default to degrees).
//   output  --units m|mm (default: the input's length unit) and --degrees (default radians;
//           kuka and fanuc are always written in degrees). The output header names any unit
//           that is not metres/radians (x_mm, a_deg), so it reads back the same without flags.
// The flags fill io::PoseConversionOptions; the job is io::ConvertPoseTable (io/pose_conversion.h);
// this file writes its result and prints the summary. Errors are hecal::InputError (exit 2, one
// line); the output is written atomically, so a failed conversion leaves no output file.
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
