// Options that validate themselves (the model: Ceres' Solver::Options::IsValid). Every options
// struct of a library job has `bool IsValid(std::string* why) const`; when a field holds an
// unusable value it returns false and sets `*why` to one line naming the FIELD, not a flag:
//
//   "Struct.field: problem (fix: what to give instead)"
//
// which is exactly the message of hecal::InputError("Struct.field", 0, problem, fix). The job
// throws that InputError (InvalidOptions), so a library user gets the field's name; the CLI maps
// the field to the flag that set it (apps/hecal/field_flags.h) before printing.
#pragma once

#include <string>

#include "hecal/core/error.h"

namespace hecal {

// Sets `*why` to the message of InputError(field, 0, problem, fix) and returns false, so an
// IsValid can `return Invalid(why, "Struct.field", "...", "...");`.
inline bool Invalid(std::string* why, const std::string& field, const std::string& problem,
                    const std::string& fix) {
  *why = InputError(field, 0, problem, fix).what();
  return false;
}

// The InputError whose message is `why` as Invalid writes it: the source is the text before the
// first ": ", the fix the text inside a trailing " (fix: …)"; any other text is the problem.
inline InputError InvalidOptions(const std::string& why) {
  const std::size_t colon = why.find(": ");
  if (colon == std::string::npos) return InputError("options", 0, why, "");
  std::string source = why.substr(0, colon);
  std::string problem = why.substr(colon + 2);
  std::string fix;
  const std::size_t open = problem.rfind(" (fix: ");
  if (open != std::string::npos && !problem.empty() && problem.back() == ')') {
    fix = problem.substr(open + 7, problem.size() - open - 8);
    problem.resize(open);
  }
  return InputError(std::move(source), 0, std::move(problem), std::move(fix));
}

}  // namespace hecal
