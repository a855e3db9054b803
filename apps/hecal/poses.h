// `hecal poses convert` (docs/cli.md#hecal-poses-convert): the flags fill
// jobs::PoseConversionOptions (choices through choice_flags.h); the job is jobs::ConvertPoseTable
// (jobs/pose_conversion.h); this file writes its result atomically and prints the summary.
#pragma once

#include <string>

#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli {

// Checks the output path, runs the conversion and writes `output`; throws hecal::InputError for
// bad flags or input.
void RunPosesConvert(const jobs::PoseConversionOptions& options, const std::string& output,
                     const Io& io);

}  // namespace hecal::cli
