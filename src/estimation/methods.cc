#include "hecal/estimation/methods.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace hecal::estimation {
namespace {

MethodInfo ClosedFormMethod(Method method, handeye::ClosedForm form) {
  const handeye::ClosedFormInfo& info = handeye::Info(form);
  return {method, info.name, info.summary, form, false};
}

// In enum order (methods.h). Built on first use: the closed forms' names are handeye's.
const std::vector<MethodInfo>& Registry() {
  using handeye::ClosedForm;
  static const std::vector<MethodInfo> methods = {
      ClosedFormMethod(Method::kTsaiLenz, ClosedForm::kTsaiLenz),
      ClosedFormMethod(Method::kParkMartin, ClosedForm::kParkMartin),
      ClosedFormMethod(Method::kHoraud, ClosedForm::kHoraud),
      ClosedFormMethod(Method::kHoraudNonlinear, ClosedForm::kHoraudNonlinear),
      ClosedFormMethod(Method::kChouKamel, ClosedForm::kChouKamel),
      ClosedFormMethod(Method::kDaniilidis, ClosedForm::kDaniilidis),
      ClosedFormMethod(Method::kAndreff, ClosedForm::kAndreff),
      ClosedFormMethod(Method::kShiuAhmad, ClosedForm::kShiuAhmad),
      ClosedFormMethod(Method::kShah, ClosedForm::kShah),
      ClosedFormMethod(Method::kLi, ClosedForm::kLi),
      {Method::kStrobl, "strobl",
       "Strobl-Hirzinger: SE(3) error metric with automatic rotation/translation weighting, "
       "nonlinear; a refinement when no noise model is known",
       std::nullopt, false},
      {Method::kMl, "ml",
       "maximum likelihood on absolute poses, X and Z jointly, residuals whitened by the robot "
       "and camera noise models; the most accurate - use it unless you need a closed form",
       std::nullopt, true},
  };
  return methods;
}

}  // namespace

std::span<const MethodInfo> AllMethods() {
  return Registry();
}

const MethodInfo& Info(Method method) {
  for (const MethodInfo& info : Registry()) {
    if (info.method == method) return info;
  }
  throw std::invalid_argument("hecal::estimation::Info: unknown method value " +
                              std::to_string(static_cast<int>(method)));
}

std::optional<Method> ParseMethod(std::string_view name) {
  for (const MethodInfo& info : Registry()) {
    if (info.name == name) return info.method;
  }
  return std::nullopt;
}

}  // namespace hecal::estimation
