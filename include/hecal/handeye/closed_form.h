// The closed-form hand–eye solvers of this layer, by name, and their dispatcher
// (docs/handeye-methods.md). The refinements `strobl` and `ml` need Ceres and live one layer up;
// the registry of every method (`--method NAME`, `--method all`) is
// hecal/estimation/methods.h, which takes the closed forms' names and summaries from here.
#pragma once

#include <span>
#include <string_view>

#include "hecal/handeye/problem.h"

namespace hecal::handeye {

// In the order `--method all` reports them: the motion-based (AX = XB) closed forms, then the
// absolute-pose (AX = YB) ones.
enum class ClosedForm {
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
};

struct ClosedFormInfo {
  ClosedForm form;
  std::string_view name;     // CLI name, e.g. "tsai-lenz"
  std::string_view summary;  // one line: what it minimises, when to use it
};

// Every closed form, in enum order.
std::span<const ClosedFormInfo> ClosedForms();
// Throws std::invalid_argument for a value outside the enum (a programming error).
const ClosedFormInfo& Info(ClosedForm form);

// Runs a closed form on station-pair motions (AX = XB methods; every pair up to 632 stations, a
// subsample linear in n above: motion.h) or on the absolute poses (shah, li). Motion-based
// methods get Z from EstimateZ. Calls CheckObservability first; throws DegenerateError on
// degenerate data.
Solution SolveClosedForm(ClosedForm form, const Problem& problem);

}  // namespace hecal::handeye
