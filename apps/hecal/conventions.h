// The command line's side of the convention check of `hecal calibrate` (both forms; the check is
// handeye/convention_check.h): the flags that fix each mistake, for its messages and notes.
#pragma once

#include "hecal/hecal.h"

namespace hecal::cli {

// handeye::ConventionWords in flags: --setup, --units, add / leave out --robot-inverse and
// --camera-inverse, and `hecal import --format matrix16` for 12/16-number files.
handeye::ConventionWords ConventionFlagWords();

}  // namespace hecal::cli
