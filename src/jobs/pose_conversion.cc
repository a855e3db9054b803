// The pose-table conversion job: see pose_conversion.h.
#include "hecal/jobs/pose_conversion.h"

#include "hecal/core/options_check.h"

namespace hecal::jobs {

bool PoseConversionOptions::IsValid(std::string* why) const {
  if (!input.empty()) return true;
  return Invalid(why, "PoseConversionOptions.input", "no input pose table given",
                 "give the path of the pose table to convert");
}

PoseConversion ConvertPoseTable(const PoseConversionOptions& options) {
  RequireValid(options);
  PoseConversion result;
  result.table = io::ReadPoseTable(options.input, options.read);
  result.write.rotation = options.to;
  result.write.units = options.units.value_or(result.table.unit);
  result.write.degrees = options.degrees;
  return result;
}

}  // namespace hecal::jobs
