// Planar robots: the fixed translation component (planar.h).
#include "hecal/handeye/planar.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "hecal/core/error.h"
#include "hecal/geometry/dense_decompositions.h"
#include "hecal/geometry/se3.h"
#include "hecal/handeye/andreff.h"
#include "hecal/handeye/motion.h"
#include "hecal/handeye/observability.h"

namespace hecal::handeye {
namespace {

// |cos| between the fixed coordinate axis and d_X below this: the coordinate does not pick a
// member of the family (the shift would be 10× the coordinate's change or more).
constexpr double kMinFixCosine = 0.1;
// A fixed component above this many metres is a unit mistake, not a hand-eye offset.
constexpr double kLargestFix = 5.0;

}  // namespace

std::string ComponentName(int axis) {
  static const char* const kNames[] = {"tx", "ty", "tz"};
  return kNames[axis];
}

TranslationFix ParseTranslationFix(std::string_view text, double metres_per_unit,
                                   std::string_view unit_name, const std::string& source) {
  const std::string written(text);
  const std::string flag = source == "--fix" ? "--fix " : source + "=";
  const auto bad = [&](const std::string& what) {
    return InputError(source, 0, what + ", got '" + written + "'",
                      "write the component of X's translation and its value, e.g. " + flag +
                          "tz=0.12 (in " + std::string(unit_name) + ") or " + flag + "tz=120mm");
  };
  const size_t equals = written.find('=');
  if (equals == std::string::npos) throw bad("expected tx=VALUE, ty=VALUE or tz=VALUE");
  const std::string name = written.substr(0, equals);
  TranslationFix fix;
  if (name == "tx") {
    fix.axis = 0;
  } else if (name == "ty") {
    fix.axis = 1;
  } else if (name == "tz") {
    fix.axis = 2;
  } else {
    throw bad("only a translation component of X can be given (tx, ty or tz)");
  }
  const char* begin = written.data() + equals + 1;
  const char* end = written.data() + written.size();
  double value = 0.0;
  const auto [rest, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || rest == begin || !std::isfinite(value))
    throw bad("expected a number after '='");
  const std::string unit(rest, end);
  double metres_per = metres_per_unit;
  if (unit == "m") {
    metres_per = 1.0;
  } else if (unit == "cm") {
    metres_per = 0.01;
  } else if (unit == "mm") {
    metres_per = 1e-3;
  } else if (!unit.empty()) {
    throw bad("unknown unit '" + unit + "' (m, cm or mm)");
  }
  fix.value = value * metres_per;
  if (std::abs(fix.value) > kLargestFix) {
    throw InputError(source, 0,
                     name + " = " + std::to_string(fix.value) +
                         " m is not a hand-eye offset (read in " +
                         (unit.empty() ? std::string(unit_name) : unit) + ")",
                     "give the unit, e.g. " + flag + name + "=" + std::string(begin, rest) + "mm");
  }
  return fix;
}

Eigen::Vector3d LeastObservedTranslation(const Problem& problem) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(TranslationNormalMatrix(problem.A));
  Eigen::Vector3d direction = eigen.eigenvectors().col(0);
  if (direction(NearestAxis(direction)) < 0.0) direction = -direction;
  return direction;
}

int NearestAxis(const Eigen::Vector3d& direction) {
  int axis = 0;
  direction.cwiseAbs().maxCoeff(&axis);
  return axis;
}

FixedTranslation ResolveFix(const Problem& problem, const TranslationFix& fix) {
  FixedTranslation fixed;
  fixed.fix = fix;
  fixed.x_direction = LeastObservedTranslation(problem);
  if (std::abs(fixed.x_direction(fix.axis)) < kMinFixCosine) {
    char direction[64];
    std::snprintf(direction, sizeof(direction), "(%.3f, %.3f, %.3f)", fixed.x_direction.x(),
                  fixed.x_direction.y(), fixed.x_direction.z());
    throw InputError("--fix", 0,
                     ComponentName(fix.axis) +
                         " of X does not fix the unobserved direction: the least observed "
                         "direction of X's translation is " +
                         direction + ", nearly perpendicular to it",
                     "fix " + ComponentName(NearestAxis(fixed.x_direction)) + " instead");
  }
  Eigen::Vector3d z = Eigen::Vector3d::Zero();
  for (const Pose& A : problem.A) z += A.linear() * fixed.x_direction;
  fixed.z_direction = z / static_cast<double>(problem.A.size());
  return fixed;
}

Solution ApplyFix(const Solution& solution, const FixedTranslation& fixed) {
  const int k = fixed.fix.axis;
  const double s = (fixed.fix.value - solution.X.translation()(k)) / fixed.x_direction(k);
  Solution moved = solution;
  moved.X.translation() += s * fixed.x_direction;
  moved.Z.translation() += s * fixed.z_direction;
  return moved;
}

Eigen::Matrix<double, 12, 1> FixGradient(const Solution& solution, const FixedTranslation& fixed) {
  Eigen::Matrix<double, 12, 1> c = Eigen::Matrix<double, 12, 1>::Zero();
  c.segment<3>(3) = solution.X.linear().row(fixed.fix.axis).transpose();  // R_Xᵀ e_k
  return c;
}

Eigen::Matrix<double, 12, 11> FixTangentBasis(const Solution& solution,
                                              const FixedTranslation& fixed) {
  // The last 11 columns of the Householder Q of c are orthonormal and perpendicular to c.
  const Eigen::Matrix<double, 12, 1> c = FixGradient(solution, fixed);
  const Eigen::HouseholderQR<Eigen::Matrix<double, 12, 1>> qr(c);
  const Eigen::Matrix<double, 12, 12> Q = qr.householderQ();
  return Q.rightCols<11>();
}

Eigen::Matrix<double, 12, 12> ConstrainedInverse(const Eigen::Matrix<double, 12, 12>& information,
                                                 const Solution& solution,
                                                 const FixedTranslation& fixed) {
  const Eigen::Matrix<double, 12, 11> U = FixTangentBasis(solution, fixed);
  const Eigen::Matrix<double, 11, 11> reduced = U.transpose() * information * U;
  const Eigen::LLT<Eigen::Matrix<double, 11, 11>> llt(reduced);
  const Eigen::Matrix<double, 11, 11> inverse =
      llt.info() == Eigen::Success
          ? Eigen::Matrix<double, 11, 11>(llt.solve(Eigen::Matrix<double, 11, 11>::Identity()))
          : Eigen::Matrix<double, 11, 11>(PseudoInverse(reduced));
  return U * inverse * U.transpose();
}

Solution FixedStart(const Problem& problem, const FixedTranslation& fixed) {
  const Pose X = SolveAndreff(StationPairMotions(problem), fixed.fix);
  return ApplyFix({X, EstimateZ(problem, X)}, fixed);
}

}  // namespace hecal::handeye
