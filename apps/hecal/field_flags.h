// The command line's names for the library's option fields. The library names the options field
// that holds a bad value (hecal::InputError's source, "CalibrateOptions.robust_loss"); the CLI
// shows the flag that set it instead ("--robust"), so every message names what the user typed.
// One table for every command (field_flags.cc); a source that is not a field (a file, a line) is
// shown as it is.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "hecal/hecal.h"

namespace hecal::cli {

// The flag that sets `field` ("StudyOptions.trials" → "--trials"); nullopt for any other source.
std::optional<std::string_view> FlagForField(std::string_view field);

// `error` with its source replaced by the flag (FlagForField), else `error` as it is.
InputError WithFlag(const InputError& error);

}  // namespace hecal::cli
