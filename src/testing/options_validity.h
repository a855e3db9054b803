// Test support (not installed): the checks every options struct's IsValid gets
// (core/options_check.h). The defaults are valid; a bad value of one field is refused with that
// field named first in `why` ("Struct.field: ..."), and RequireValid throws it as a
// hecal::InputError whose source is the field and whose fix is not empty.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"

namespace hecal::testing {

template <class Options>
::testing::AssertionResult IsValidOptions(const Options& options) {
  std::string why;
  if (options.IsValid(&why)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "refused: " << why;
}

// `base` with `change` applied is refused, naming `field`.
template <class Options, class Change>
::testing::AssertionResult RefusesNaming(Options options, std::string_view field, Change change) {
  change(options);
  std::string why;
  if (options.IsValid(&why)) return ::testing::AssertionFailure() << "accepted a bad " << field;
  if (why.rfind(std::string(field) + ": ", 0) != 0) {
    return ::testing::AssertionFailure() << "expected " << field << " named first, got: " << why;
  }
  if (options.IsValid(nullptr)) return ::testing::AssertionFailure() << "no why: accepted";
  try {
    RequireValid(options);
  } catch (const InputError& error) {
    if (error.source() != field || error.fix().empty() || error.problem().empty()) {
      return ::testing::AssertionFailure() << "RequireValid threw " << error.what();
    }
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "RequireValid did not throw for " << field;
}

}  // namespace hecal::testing
