#include "hecal/handeye/closed_form.h"

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

// In enum order (closed_form.h).
constexpr ClosedFormInfo kClosedForms[] = {
    {ClosedForm::kTsaiLenz, "tsai-lenz",
     "Tsai-Lenz 1989: rotation from modified Rodrigues vectors by linear least squares, then "
     "translation; the classic, fast, fine with varied rotations"},
    {ClosedForm::kParkMartin, "park-martin",
     "Park-Martin 1994: rotation minimising the sum of squared rotation-vector errors "
     "|log R_A - R_X log R_B|^2 (SVD), then translation; robust general-purpose closed form"},
    {ClosedForm::kHoraud, "horaud",
     "Horaud-Dornaika 1995 R then t: rotation minimising the quaternion error |q_A q - q q_B|^2 "
     "(4x4 eigenproblem), then translation; fast and accurate closed form"},
    {ClosedForm::kHoraudNonlinear, "horaud-nonlinear",
     "Horaud-Dornaika 1995 R and t: rotation and translation errors of the motions minimised "
     "together (Levenberg-Marquardt); better translations than the R-then-t methods"},
    {ClosedForm::kChouKamel, "chou-kamel",
     "Chou-Kamel 1991: rotation as the null vector (SVD) of a quaternion system on unit axes, "
     "every motion equally weighted, then translation"},
    {ClosedForm::kDaniilidis, "daniilidis",
     "Daniilidis 1999: rotation and translation together from the dual-quaternion null space "
     "(SVD), rejecting inconsistent motions; good when translations are accurate"},
    {ClosedForm::kAndreff, "andreff",
     "Andreff 2001: rotation and translation jointly by linear least squares on the Kronecker "
     "form (12 unknowns), rotation orthogonalised, translation re-solved; no angles or axes"},
    {ClosedForm::kShiuAhmad, "shiu-ahmad",
     "Shiu-Ahmad 1989: rotation from each motion's one-parameter family (axis equations) by "
     "linear least squares, then translation; historical reference"},
    {ClosedForm::kShah, "shah",
     "Shah 2013: X and Z together from absolute poses (AX = YB) via the Kronecker product; "
     "avoids the correlated noise of motions"},
    {ClosedForm::kLi, "li",
     "Li 2010: X and Z together from absolute poses (AX = YB) by linear least squares on the "
     "Kronecker form, then orthogonalised; simple AX = YB alternative"},
};

using MotionSolver = Pose (*)(const std::vector<Motion>&);
using PoseSolver = Solution (*)(const Problem&);

// AX = XB solvers on station-pair motions (motion.h; Z from EstimateZ) …
constexpr std::pair<ClosedForm, MotionSolver> kMotionSolvers[] = {
    {ClosedForm::kTsaiLenz, SolveTsaiLenz},   {ClosedForm::kParkMartin, SolveParkMartin},
    {ClosedForm::kHoraud, SolveHoraud},       {ClosedForm::kHoraudNonlinear, SolveHoraudNonlinear},
    {ClosedForm::kChouKamel, SolveChouKamel}, {ClosedForm::kDaniilidis, SolveDaniilidis},
    {ClosedForm::kAndreff, SolveAndreff},     {ClosedForm::kShiuAhmad, SolveShiuAhmad},
};
// … and AX = YB solvers on the absolute poses (X and Z together).
constexpr std::pair<ClosedForm, PoseSolver> kPoseSolvers[] = {
    {ClosedForm::kShah, SolveShah},
    {ClosedForm::kLi, SolveLi},
};

}  // namespace

std::span<const ClosedFormInfo> ClosedForms() {
  return kClosedForms;
}

const ClosedFormInfo& Info(ClosedForm form) {
  for (const ClosedFormInfo& info : kClosedForms) {
    if (info.form == form) return info;
  }
  throw std::invalid_argument("hecal::handeye::Info: unknown closed form value " +
                              std::to_string(static_cast<int>(form)));
}

Solution SolveClosedForm(ClosedForm form, const Problem& problem) {
  const ClosedFormInfo& info = Info(form);
  CheckObservability(problem);
  for (const auto& [pose_form, solve] : kPoseSolvers) {
    if (pose_form == form) return solve(problem);
  }
  for (const auto& [motion_form, solve] : kMotionSolvers) {
    if (motion_form == form) {
      const Pose X = solve(StationPairMotions(problem));
      return {X, EstimateZ(problem, X)};
    }
  }
  throw std::invalid_argument("SolveClosedForm: no solver for " + std::string(info.name));
}

}  // namespace hecal::handeye
