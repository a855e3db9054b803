// The hand–eye methods by name (docs/cli.md#methods) and the dispatcher for the
// closed-form ones. The refinements `strobl` and `ml` need Ceres and live in the estimation
// layer (hecal/estimation/calibrate.h), which dispatches every method.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "hecal/handeye/problem.h"

namespace hecal::handeye {

enum class Method {
  kTsaiLenz,
  kParkMartin,
  kHoraud,
  kHoraudNonlinear,
  kChouKamel,
  kDaniilidis,
  kAndreff,
  kShiuAhmad,
  kShah,
  kLi,
  kStrobl,
  kMl,
};

struct MethodInfo {
  Method method;
  std::string_view name;     // CLI name, e.g. "tsai-lenz"
  std::string_view summary;  // one line: what it minimises, when to use it
  bool closed_form;          // false for strobl / ml (iterative refinements)
};

// Every method, in the order `--method all` reports them.
std::span<const MethodInfo> AllMethods();
const MethodInfo& Info(Method method);
std::optional<Method> ParseMethod(std::string_view name);

// Runs a closed-form method (closed_form == true) on station-pair motions (AX = XB methods;
// every pair up to 632 stations, a subsample linear in n above: motion.h) or on the absolute
// poses (shah, li). Motion-based methods get Z from EstimateZ. Calls
// CheckObservability first; throws DegenerateError on degenerate data.
Solution SolveClosedForm(Method method, const Problem& problem);

}  // namespace hecal::handeye
