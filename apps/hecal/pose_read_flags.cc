// The flags of one robot pose table: see pose_read_flags.h.
#include "pose_read_flags.h"

#include "choice_flags.h"

namespace hecal::cli {

void AddRobotReadFlags(CLI::App& command, io::PoseReadOptions& read, const std::string& prefix,
                       const std::string& inverse_frames) {
  AddLengthUnitFlag(command, "--units", read.units,
                    prefix + "length unit of columns without a suffix (m or mm)");
  command.add_flag("--degrees", read.degrees, prefix + "angles without a suffix are in degrees");
  AddEulerFlag(command, "--euler", read.euler, prefix + "Euler sequence of a1,a2,a3 columns");
  command.add_flag("--robot-inverse", read.invert,
                   prefix + "the file holds " + inverse_frames + ": invert every pose");
}

}  // namespace hecal::cli
