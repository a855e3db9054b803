// The registry of every hand–eye method by name: what `--method NAME` and `--method all` of
// `hecal calibrate`, `hecal simulate` and `hecal bench` accept (docs/cli.md#methods), what the
// studies, the benchmark and the tests run. This layer sees every method: the closed forms of
// hecal/handeye/closed_form.h (their names and summaries are the ones given there) and the
// refinements `strobl` (strobl.h) and `ml` (ml.h), which start from the closed forms
// (initialization.h). Calibrate (calibrate.h) runs any of them; equations in
// docs/handeye-methods.md.
//
// `global`, the target-free certified method (docs/global.md), reads point matches instead of
// poses and is not one of these.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "hecal/handeye/closed_form.h"

namespace hecal::estimation {

// In the order `--method all` reports them: the closed forms (handeye::ClosedForm order), then
// the refinements.
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
  // The handeye solver of a closed form (handeye::SolveClosedForm); nullopt for the iterative
  // refinements strobl and ml.
  std::optional<handeye::ClosedForm> closed_form;
  // The method's own Gauss–Newton information is its linear covariance (ml): kLinear is its
  // default and needs no dense input covariance at any station count. false: the covariance is
  // propagated through the solver (covariance_method.h, DefaultCovarianceMethod).
  bool analytic_covariance;
};

// Every method, in enum order.
std::span<const MethodInfo> AllMethods();
// Throws std::invalid_argument for a value outside the enum (a programming error).
const MethodInfo& Info(Method method);
// The method of a CLI name (exact, lower case); nullopt for any other text, "all" included.
std::optional<Method> ParseMethod(std::string_view name);

}  // namespace hecal::estimation
