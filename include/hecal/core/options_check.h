// Options that validate themselves (the model is Ceres' Solver::Options::IsValid). Every options
// struct of a library job has
//
//   bool IsValid(std::string* why) const;
//
// which returns false at the first bad value and writes `why` as
//
//   Struct.field: what is wrong (fix: what to give instead)
//
// naming the field, never a command-line flag (the CLI maps fields to flags, apps/hecal/
// field_flags.h). A job calls RequireValid on its options before any work; it throws that text
// as a hecal::InputError whose source is the field, so a caller that binds the field to a flag
// or a file key can say which. The ranges checked are facts of the library (a noise level no
// device has, a sample count that would not fit in memory), not of one caller.
#pragma once

#include <string>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/core/limits.h"

namespace hecal {

// For IsValid implementations: writes "field: problem (fix: fix)" to `why` (when non-null) and
// returns false.
inline bool Invalid(std::string* why, std::string_view field, std::string_view problem,
                    std::string_view fix) {
  if (why != nullptr) {
    *why = field;
    *why += ": ";
    *why += problem;
    *why += " (fix: ";
    *why += fix;
    *why += ')';
  }
  return false;
}

// For IsValid implementations: a worker-thread count in 0 … kMaxThreads (0 = every core), or
// Invalid naming `field`.
inline bool ThreadCountValid(int threads, std::string_view field, std::string* why) {
  if (threads >= 0 && threads <= kMaxThreads) return true;
  return Invalid(why, field,
                 "must be a whole number from 0 to " + std::to_string(kMaxThreads) + ", got " +
                     std::to_string(threads),
                 "give a thread count in that range (0 = every core)");
}

// The InputError of a `why` written by Invalid: source the field, problem and fix as written. A
// text without a field prefix becomes the problem of source "options".
inline InputError OptionsError(const std::string& why) {
  const size_t colon = why.find(": ");
  std::string source = colon == std::string::npos ? "options" : why.substr(0, colon);
  std::string rest = colon == std::string::npos ? why : why.substr(colon + 2);
  const size_t fix = rest.rfind(" (fix: ");
  if (fix != std::string::npos && rest.back() == ')') {
    std::string fix_text = rest.substr(fix + 7, rest.size() - fix - 8);
    rest.resize(fix);
    return InputError(std::move(source), 0, std::move(rest), std::move(fix_text));
  }
  return InputError(std::move(source), 0, std::move(rest), "");
}

// Throws OptionsError(why) when !options.IsValid(&why).
template <class Options>
void RequireValid(const Options& options) {
  std::string why;
  if (!options.IsValid(&why)) throw OptionsError(why);
}

}  // namespace hecal
