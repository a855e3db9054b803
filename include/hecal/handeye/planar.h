// Planar robots (SCARA, a mobile base, a turntable): every relative rotation of the robot is
// about one axis n, so one direction of X's translation cannot be observed, and hecal calibrates
// the rest with that component given by the user (`--fix tz=VALUE`, docs/planar.md).
//
// Why one direction: with the motions A_ij X = X B_ij (motion.h), the translation rows are
//        (R_Aij − I) t_X = R_X t_Bij − t_Aij,
// and every R_Aij − I annihilates the common axis n (in X's parent frame: the gripper frame
// eye-in-hand, the robot base frame eye-to-hand; observability.h). So X's translation is fixed
// up to t_X + s·n (Tsai & Lenz 1989; Shiu & Ahmad 1989), and on absolute poses Z = A_i X B_i
// (problem.h) Z's translation moves with it by s·R_Ai n — the same vector for every station, as
// R_Ai = R_A0 · Rot(n, θ_i) leaves n fixed. The one-parameter family
//        X(s): t_X + s·d_X,   Z(s): t_Z + s·d_Z,   d_X = n,   d_Z = mean_i R_Ai n        (P1)
// fits every station equally (exactly when the measured axes are parallel, to within the robot's
// rotation noise otherwise). X's rotation and the rest of both translations are observed when the
// robot also translates in the plane (R_X t_B enters (T1) above).
//
// The fix: the user gives one component of X's translation in X's parent frame — tx, ty or tz,
// the literal coordinate, e.g. tz of T_gripper_camera for a camera on a SCARA's flange — and the
// member of (P1) with that coordinate is the estimate. The component must not be perpendicular to
// n (it would not pick a member); the closest to n is the natural choice, and it is the one the
// degeneracy message names.
// Solvers: ml minimises on the constraint surface (loop_solver.h, the step restricted to the
// tangent perpendicular to ∂(e_kᵀ t_X)/∂δ, then moved back along (P1)); its covariance is the
// constrained inverse information U (Uᵀ H U)⁻¹ Uᵀ, U an orthonormal basis of that tangent — the
// covariance of the observable part, zero along the fixed coordinate. Its start is Andreff's
// linear system with the fixed coordinate as an equality constraint (andreff.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>

#include "hecal/handeye/problem.h"

namespace hecal::handeye {

// One component of X's translation, given: t_X(axis) = value (metres, X's parent frame).
struct TranslationFix {
  int axis = 2;  // 0, 1, 2: tx, ty, tz
  double value = 0.0;
};

// "tx" | "ty" | "tz" for axis 0, 1, 2.
std::string ComponentName(int axis);

// "tx|ty|tz=VALUE[m|cm|mm]" (`--fix`, Python's fix=) → the fix in metres; a VALUE without a unit
// is in the caller's default unit (metres_per_unit, named unit_name in messages). Throws
// hecal::InputError with `source` when it does not parse, or when the value is above 5 m (a unit
// mistake: the message asks for the unit).
TranslationFix ParseTranslationFix(std::string_view text, double metres_per_unit,
                                   std::string_view unit_name, const std::string& source);

// A fix resolved on a problem: the directions (P1) along which a solution is moved onto it.
struct FixedTranslation {
  TranslationFix fix;
  Eigen::Vector3d x_direction = Eigen::Vector3d::UnitZ();  // d_X, unit, X's parent frame
  Eigen::Vector3d z_direction = Eigen::Vector3d::UnitZ();  // d_Z, Z's parent frame
};

// The least observed direction of X's translation: the eigenvector of the smallest eigenvalue of
// the translation normal matrix (observability.h), the common rotation axis for a planar robot;
// its sign makes its largest coordinate positive.
Eigen::Vector3d LeastObservedTranslation(const Problem& problem);

// The index (0, 1, 2) of the coordinate axis closest to `direction`.
int NearestAxis(const Eigen::Vector3d& direction);

// Resolves `fix` on `problem`: d_X the least observed direction, d_Z by (P1). Throws
// hecal::InputError (source "--fix") when the fixed coordinate is (nearly) perpendicular to d_X,
// naming the component to fix instead.
FixedTranslation ResolveFix(const Problem& problem, const TranslationFix& fix);

// `solution` moved along (P1) until X's fixed coordinate has the given value.
Solution ApplyFix(const Solution& solution, const FixedTranslation& fixed);

// ∂(e_kᵀ t_X)/∂δ at `solution` for right perturbations δ = (δX, δZ), (ω, v) order: the fixed
// coordinate changes with (R_Xᵀ e_k)ᵀ v_X to first order.
Eigen::Matrix<double, 12, 1> FixGradient(const Solution& solution, const FixedTranslation& fixed);

// An orthonormal basis (12 × 11) of the perturbations that keep the fixed coordinate (to first
// order): the tangent of the constraint surface at `solution`.
Eigen::Matrix<double, 12, 11> FixTangentBasis(const Solution& solution,
                                              const FixedTranslation& fixed);

// U (Uᵀ H U)⁻¹ Uᵀ with U = FixTangentBasis: the inverse of an information matrix H restricted to
// the constraint surface (zero along the fixed coordinate).
Eigen::Matrix<double, 12, 12> ConstrainedInverse(const Eigen::Matrix<double, 12, 12>& information,
                                                 const Solution& solution,
                                                 const FixedTranslation& fixed);

// A starting solution on planar data: Andreff's linear system (andreff.h) with the fixed
// coordinate as a constraint, Z by EstimateZ, then ApplyFix. Throws DegenerateError when even
// with the fix the data do not determine X (no rotation, or no translation in the plane).
Solution FixedStart(const Problem& problem, const FixedTranslation& fixed);

}  // namespace hecal::handeye
