// The command line's own syntax of whole numbers, their lists and lists of finite numbers
// (docs/cli.md#exit-codes-and-errors states the rule for every kind of value; noise levels are read
// by list_flags.h, --pixel-sigma by calibrate.h). Ranges are facts of the library, checked by the
// options' IsValid (core/options_check.h) and shown as flags (field_flags.h). A bad value is a
// hecal::InputError naming the flag and the text (exit 2), before any work.
//
// CLI11 2.1.2 reads integers with strtoll base 0 ("010" is 8, "0x10" 16) and unsigned ones with
// strtoull ("-1" becomes 2^64 − 1), so every whole-number flag is bound through AddWholeNumber:
// the text is read as a decimal number of the field's type and handed to CLI11 as its plain
// decimal.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace hecal::cli {

// Binds `flag` to `value` (int, std::int64_t or std::uint64_t) through the whole-number rule
// above; returns the option for further settings (default text, group).
template <class T>
CLI::Option* AddWholeNumber(CLI::App& command, const std::string& flag, T& value,
                            const std::string& help);

// --seed of `hecal simulate` and `hecal bench`: the whole-number rule, default shown.
CLI::Option* AddSeedFlag(CLI::App& command, std::uint64_t& seed);

// Binds `flag` to `values`: one argument, comma separated whole numbers (SplitList, list_flags.h;
// the rule above per item).
CLI::Option* AddWholeNumberList(CLI::App& command, const std::string& flag,
                                std::vector<int>& values, const std::string& help);

// `count` comma-separated finite numbers from flag `flag`, or with count kAnyCount one or more
// (InputError naming the flag otherwise). `what` describes them for the fix, e.g.
// "TX,TY,TZ,RX,RY,RZ".
constexpr std::size_t kAnyCount = 0;
std::vector<double> ParseNumberList(const std::string& flag, const std::string& text,
                                    std::size_t count, const std::string& what);

// One finite number (ParseNumberList with count 1).
double ParseNumber(const std::string& flag, const std::string& text, const std::string& what);

}  // namespace hecal::cli
