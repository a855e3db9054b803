// Test support (not installed): the hand–eye methods by the names `hecal calibrate --method all`
// runs (docs/cli.md#methods), and a method run by name the way `--method NAME` runs it: through
// estimation::Calibrate, the one dispatcher of every method (closed forms, strobl, ml). The
// method registry is named in Registry() only, so the typed solver suite
// (src/estimation/every_method_test.cc) follows the registry wherever it lives.
//
// SolveByName leaves out what is not the solve: outlier rejection (it would drop stations of
// the data a property is stated on), the covariance and its model check. Errors are
// estimation::Calibrate's: hecal::DegenerateError on degenerate data; an unknown name is a
// test-setup mistake (std::invalid_argument).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/methods.h"
#include "hecal/handeye/problem.h"

namespace hecal::testing {

// Every method, in the order `--method all` reports them.
inline auto Registry() {
  return estimation::AllMethods();
}

inline std::vector<std::string> CalibrateMethodNames() {
  std::vector<std::string> names;
  for (const auto& info : Registry()) names.emplace_back(info.name);
  return names;
}

inline estimation::CalibrationResult SolveByName(const std::string& name,
                                                 const handeye::Problem& problem) {
  for (const auto& info : Registry()) {
    if (info.name != name) continue;
    estimation::CalibrateOptions options;
    options.method = info.method;
    options.reject_outliers = false;
    options.covariance.method = estimation::CovarianceMethod::kNone;
    options.model_check = false;
    return estimation::Calibrate(problem, options);
  }
  throw std::invalid_argument("SolveByName: no method named '" + name + "'");
}

}  // namespace hecal::testing
