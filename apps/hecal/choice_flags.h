// Flags whose value is one of a few names, each bound in one place so that every command reads
// the same text the same way and says the same thing about a wrong one. A choice is parsed when
// CLI11 reads the flag; text that names no choice is a hecal::InputError (exit 2):
//
//   FLAG: unknown WHAT 'TEXT' (fix: use ...)
//
// (CLI11 runs the parse as it reads the flag, so a wrong choice is reported before a missing
// required flag and before --help.)
//
// The choices several commands share (docs/cli.md, docs/conventions.md):
//   --setup            eye-in-hand | eye-to-hand [| auto]   handeye::Setup (handeye/problem.h)
//   --units, ...       m | mm                               io::LengthUnit (io/units.h)
//   --euler            three axis letters, lowercase = extrinsic, uppercase = intrinsic
//                      (geometry/euler.h)
// Used by `hecal import` (--format, --units, --setup) and `hecal poses convert` (--to, --units,
// --input-units, --euler); `hecal calibrate` (--setup with auto, --units, --euler), `hecal pose`
// (--units), `hecal bench` and `hecal simulate` (--setup) read the same choices.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/geometry/euler.h"
#include "hecal/handeye/problem.h"
#include "hecal/io/units.h"

namespace hecal::cli {

// Binds `flag` to `target` (a T, or anything a T assigns to, such as std::optional<T>): `parse`
// reads the text, nullopt meaning "unknown WHAT 'TEXT'" with `fix`.
template <class T, class Target>
CLI::Option* AddChoice(CLI::App& command, const std::string& flag, Target& target,
                       std::function<std::optional<T>(std::string_view)> parse,
                       const std::string& what, const std::string& fix, const std::string& help) {
  return command.add_option_function<std::string>(
      flag,
      [&target, flag, parse, what, fix](const std::string& text) {
        const std::optional<T> value = parse(text);
        if (!value) throw InputError(flag, 0, "unknown " + what + " '" + text + "'", fix);
        target = *value;
      },
      help);
}

// Whether `auto` (nullopt: the convention check picks the setup) is one of the choices.
enum class SetupChoices { kGiven, kGivenOrAuto };

// --setup: eye-in-hand (camera on the robot) | eye-to-hand (camera fixed) [| auto].
CLI::Option* AddSetupFlag(CLI::App& command, std::optional<handeye::Setup>& setup,
                          SetupChoices choices, const std::string& help);

// A length unit m | mm ("unknown unit"; io::ParseLengthUnit).
template <class Target>
CLI::Option* AddLengthUnitFlag(CLI::App& command, const std::string& flag, Target& unit,
                               const std::string& help) {
  return AddChoice<io::LengthUnit>(command, flag, unit, io::ParseLengthUnit, "unit", "use m or mm",
                                   help);
}

// An Euler sequence of a1,a2,a3 columns (EulerSequence::Parse).
CLI::Option* AddEulerFlag(CLI::App& command, const std::string& flag,
                          std::optional<EulerSequence>& sequence, const std::string& help);

}  // namespace hecal::cli
