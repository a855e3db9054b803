// The import job: see import_job.h.
#include "hecal/jobs/import.h"

#include "hecal/core/options_check.h"
#include "hecal/version.h"

namespace hecal::jobs {

bool ImportJobOptions::RobotOnly() const {
  return format == io::ImportFormat::kMatrix16 && inputs.size() == 1;
}

bool ImportJobOptions::IsValid(std::string* why) const {
  const std::string name(io::ImportFormatName(format));
  if (robot.empty()) {
    return Invalid(why, "ImportJobOptions.robot", "is empty",
                   "give the path of the robot table (T_base_gripper)");
  }
  if (camera.empty() && !RobotOnly()) {
    return Invalid(why, "ImportJobOptions.camera", "is required for format " + name,
                   "give the path of the camera table (only a robot-only matrix16 import may "
                   "omit it)");
  }
  if (!camera.empty() && RobotOnly()) {
    return Invalid(why, "ImportJobOptions.camera", "given, but matrix16 got only a robot file",
                   "pass the camera matrix file after the robot file, or leave the camera table "
                   "out");
  }
  if (!intrinsics.empty() && format != io::ImportFormat::kTabb) {
    return Invalid(why, "ImportJobOptions.intrinsics",
                   "only tabb sources hold intrinsics (cali.txt), not " + name,
                   "leave the intrinsics file out");
  }
  return read.IsValid(format, why);
}

ImportJob ImportSamples(const ImportJobOptions& options) {
  RequireValid(options);
  ImportJob job;
  job.imported = io::ImportFiles(options.format, options.inputs, options.read);
  job.texts = io::FormatImportedPoses(
      job.imported, "written by hecal " + std::string(kVersion) + " import --format " +
                        std::string(io::ImportFormatName(options.format)));
  if (!options.intrinsics.empty() && !job.texts.intrinsics) {
    throw InputError(options.inputs.back(), 0,
                     "the images do not share one camera model (intrinsics differ between "
                     "lines), so no single camera.yaml can be written",
                     "leave the intrinsics file out");
  }
  job.warnings = job.imported.robot.warnings;
  if (job.imported.camera) {
    job.warnings.insert(job.warnings.end(), job.imported.camera->warnings.begin(),
                        job.imported.camera->warnings.end());
  }
  return job;
}

}  // namespace hecal::jobs
