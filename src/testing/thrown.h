// Test support (not installed): the hecal error an action throws, for tests that then check its
// parts (source, line, problem, fix, the unobservable part).
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "hecal/core/error.h"

namespace hecal::testing {

template <typename Error>
Error EmptyError();
template <>
inline InputError EmptyError<InputError>() {
  return InputError("", 0, "", "");
}
template <>
inline DegenerateError EmptyError<DegenerateError>() {
  return DegenerateError("", "");
}

// The Error that `action` throws; fails the test (and returns an empty Error) when it throws none.
template <typename Error, typename Action>
Error Thrown(Action&& action) {
  try {
    action();
  } catch (const Error& error) {
    return error;
  }
  ADD_FAILURE() << "nothing thrown";
  return EmptyError<Error>();
}

// An InputError that names `source`, `line`, contains `problem` and says how to fix it.
inline void ExpectInputError(const InputError& error, const std::string& source, int line,
                             const std::string& problem) {
  EXPECT_EQ(error.source(), source);
  EXPECT_EQ(error.line(), line) << error.what();
  EXPECT_THAT(error.problem(), ::testing::HasSubstr(problem)) << error.what();
  EXPECT_FALSE(error.fix().empty()) << error.what();
}

}  // namespace hecal::testing
