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
// Used by `hecal calibrate` (--setup with auto, --units, --euler, --robust, --covariance),
// `hecal import` (--format, --units, --setup), `hecal poses convert` (--to, --units,
// --input-units, --euler), `hecal pose` (--units) and `hecal bench` (--setup); `hecal simulate`
// reads its lists of choices with ParseChoiceList (list_flags.h), the same reading per item.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "hecal/hecal.h"
#include "list_flags.h"

namespace hecal::cli {

// Binds `flag` to `target` (a T, or anything a T assigns to, such as std::optional<T>): the text
// is read by ParseChoice (list_flags.h) with `parse`, an unknown one is "unknown WHAT 'TEXT'"
// with the fix "use CHOICES".
template <class T, class Target>
CLI::Option* AddChoice(CLI::App& command, const std::string& flag, Target& target,
                       std::function<std::optional<T>(std::string_view)> parse,
                       const std::string& what, const std::string& choices,
                       const std::string& help) {
  return command.add_option_function<std::string>(
      flag,
      [&target, flag, parse, what, choices](const std::string& text) {
        target = ParseChoice(flag, text, parse, what, choices);
      },
      help);
}

// --setup: eye-in-hand (camera on the robot) | eye-to-hand (camera fixed), into a handeye::Setup
// or a std::optional of one.
template <class Target>
CLI::Option* AddSetupFlag(CLI::App& command, Target& setup, const std::string& help) {
  return AddChoice<handeye::Setup>(
      command, "--setup", setup, handeye::ParseSetup, "setup",
      "eye-in-hand (camera on the robot) or eye-to-hand (camera fixed)", help);
}

// --setup with `auto` as a third choice: nullopt (the convention check picks the setup).
CLI::Option* AddSetupOrAutoFlag(CLI::App& command, std::optional<handeye::Setup>& setup,
                                const std::string& help);

// A length unit m | mm ("unknown unit"; io::ParseLengthUnit).
template <class Target>
CLI::Option* AddLengthUnitFlag(CLI::App& command, const std::string& flag, Target& unit,
                               const std::string& help) {
  return AddChoice<io::LengthUnit>(command, flag, unit, io::ParseLengthUnit, "unit", "m or mm",
                                   help);
}

// An Euler sequence of a1,a2,a3 columns (EulerSequence::Parse).
CLI::Option* AddEulerFlag(CLI::App& command, const std::string& flag,
                          std::optional<EulerSequence>& sequence, const std::string& help);

}  // namespace hecal::cli
