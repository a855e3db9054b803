#include "hecal/handeye/methods.h"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hecal/handeye/andreff.h"
#include "hecal/handeye/chou_kamel.h"
#include "hecal/handeye/daniilidis.h"
#include "hecal/handeye/horaud.h"
#include "hecal/handeye/horaud_nonlinear.h"
#include "hecal/handeye/li.h"
#include "hecal/handeye/motion.h"
#include "hecal/handeye/observability.h"
#include "hecal/handeye/park_martin.h"
#include "hecal/handeye/shah.h"
#include "hecal/handeye/shiu_ahmad.h"
#include "hecal/handeye/tsai_lenz.h"

namespace hecal::handeye {
namespace {

// Order of `--method all`: the enum order (docs/cli.md): the motion-based closed forms, the
// absolute-pose closed forms, then the refinements.
constexpr MethodInfo kMethods[] = {
    {Method::kTsaiLenz, "tsai-lenz",
     "Tsai-Lenz 1989: rotation from modified Rodrigues vectors by linear least squares, then "
     "translation; the classic, fast, fine with varied rotations",
     true},
    {Method::kParkMartin, "park-martin",
     "Park-Martin 1994: rotation minimising the sum of squared rotation-vector errors "
     "|log R_A - R_X log R_B|^2 (SVD), then translation; robust general-purpose closed form",
     true},
    {Method::kHoraud, "horaud",
     "Horaud-Dornaika 1995 R then t: rotation minimising the quaternion error |q_A q - q q_B|^2 "
     "(4x4 eigenproblem), then translation; fast and accurate closed form",
     true},
    {Method::kHoraudNonlinear, "horaud-nonlinear",
     "Horaud-Dornaika 1995 R and t: rotation and translation errors of the motions minimised "
     "together (Levenberg-Marquardt); better translations than the R-then-t methods",
     true},
    {Method::kChouKamel, "chou-kamel",
     "Chou-Kamel 1991: rotation as the null vector (SVD) of a quaternion system on unit axes, "
     "every motion equally weighted, then translation",
     true},
    {Method::kDaniilidis, "daniilidis",
     "Daniilidis 1999: rotation and translation together from the dual-quaternion null space "
     "(SVD), rejecting inconsistent motions; good when translations are accurate",
     true},
    {Method::kAndreff, "andreff",
     "Andreff 2001: rotation and translation jointly by linear least squares on the Kronecker "
     "form (12 unknowns), rotation orthogonalised, translation re-solved; no angles or axes",
     true},
    {Method::kShiuAhmad, "shiu-ahmad",
     "Shiu-Ahmad 1989: rotation from each motion's one-parameter family (axis equations) by "
     "linear least squares, then translation; historical reference",
     true},
    {Method::kShah, "shah",
     "Shah 2013: X and Z together from absolute poses (AX = YB) via the Kronecker product; "
     "avoids the correlated noise of motions",
     true},
    {Method::kLi, "li",
     "Li 2010: X and Z together from absolute poses (AX = YB) by linear least squares on the "
     "Kronecker form, then orthogonalised; simple AX = YB alternative",
     true},
    {Method::kStrobl, "strobl",
     "Strobl-Hirzinger: SE(3) error metric with automatic rotation/translation weighting, "
     "nonlinear; a refinement when no noise model is known",
     false},
    {Method::kMl, "ml",
     "maximum likelihood on absolute poses, X and Z jointly, residuals whitened by the robot and "
     "camera noise models; the most accurate - use it unless you need a closed form",
     false},
};

using MotionSolver = Pose (*)(const std::vector<Motion>&);
using PoseSolver = Solution (*)(const Problem&);

// AX = XB solvers on station-pair motions (motion.h; Z from EstimateZ) …
constexpr std::pair<Method, MotionSolver> kMotionSolvers[] = {
    {Method::kTsaiLenz, SolveTsaiLenz},   {Method::kParkMartin, SolveParkMartin},
    {Method::kHoraud, SolveHoraud},       {Method::kHoraudNonlinear, SolveHoraudNonlinear},
    {Method::kChouKamel, SolveChouKamel}, {Method::kDaniilidis, SolveDaniilidis},
    {Method::kAndreff, SolveAndreff},     {Method::kShiuAhmad, SolveShiuAhmad},
};
// … and AX = YB solvers on the absolute poses (X and Z together).
constexpr std::pair<Method, PoseSolver> kPoseSolvers[] = {
    {Method::kShah, SolveShah},
    {Method::kLi, SolveLi},
};

}  // namespace

std::span<const MethodInfo> AllMethods() {
  return kMethods;
}

const MethodInfo& Info(Method method) {
  for (const MethodInfo& info : kMethods) {
    if (info.method == method) return info;
  }
  throw std::invalid_argument("hecal::handeye::Info: unknown method value " +
                              std::to_string(static_cast<int>(method)));
}

std::optional<Method> ParseMethod(std::string_view name) {
  for (const MethodInfo& info : kMethods) {
    if (info.name == name) return info.method;
  }
  return std::nullopt;
}

Solution SolveClosedForm(Method method, const Problem& problem) {
  const MethodInfo& info = Info(method);
  if (!info.closed_form) {
    throw std::invalid_argument("method '" + std::string(info.name) +
                                "' is an iterative refinement: run it through "
                                "hecal/estimation/calibrate.h, not SolveClosedForm");
  }
  CheckObservability(problem);
  for (const auto& [pose_method, solve] : kPoseSolvers) {
    if (pose_method == method) return solve(problem);
  }
  for (const auto& [motion_method, solve] : kMotionSolvers) {
    if (motion_method == method) {
      const Pose X = solve(StationPairMotions(problem));
      return {X, EstimateZ(problem, X)};
    }
  }
  throw std::invalid_argument("SolveClosedForm: no solver for method " + std::string(info.name));
}

}  // namespace hecal::handeye
