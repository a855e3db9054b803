// The flags that say how to read one robot pose table, bound into io::PoseReadOptions (the rules:
// docs/pose-files.md): --units m|mm, --degrees, --euler SEQ and --robot-inverse. Used by the
// commands that read a single robot table: `hecal report --robot` and `hecal pivot --robot`.
// (`hecal calibrate` reads two tables and binds the same flags to both, calibrate.h.)
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "hecal/hecal.h"

namespace hecal::cli {

// `prefix` starts every flag's help (e.g. "With --robot: "), `inverse_frames` names what the file
// holds with --robot-inverse (e.g. "T_gripper_base").
void AddRobotReadFlags(CLI::App& command, io::PoseReadOptions& read, const std::string& prefix,
                       const std::string& inverse_frames);

}  // namespace hecal::cli
