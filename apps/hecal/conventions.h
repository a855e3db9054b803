// The command line's side of the convention check of `hecal calibrate` (both forms; the check is
// handeye/convention_check.h): the flags that fix each mistake, for its messages and notes.
#pragma once

#include "hecal/handeye/convention_check.h"
#include "hecal/io/pose_table.h"

namespace hecal::cli {

// handeye::ConventionWords in flags: --setup, --units, add / leave out --robot-inverse and
// --camera-inverse, and `hecal import --format matrix16` for 12/16-number files.
handeye::ConventionWords ConventionFlagWords();

// The table's rotations were quaternion columns (their order can be mislabelled).
bool HasQuaternionColumns(const io::PoseTable& table);

}  // namespace hecal::cli
