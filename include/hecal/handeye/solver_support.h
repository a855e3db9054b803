// Small pieces shared by the linear solvers of this module (Daniilidis, Andreff, Shah, Li,
// Horaud–Dornaika nonlinear).
//  - Minimum input: throw DegenerateError when there are too few motions / stations to solve
//    at all (2 motions with non-parallel axes, i.e. 3 stations, are the minimum of AX = XB and
//    of AX = ZB alike).
//  - TranslationScale: the RMS translation magnitude of the inputs (1 when every translation is
//    zero). Solvers whose equations mix dimensionless rotation rows with length-unit translation
//    rows divide translations by it, so that their noisy solution does not depend on whether the
//    data are in metres or millimetres; noise-free solutions are unaffected.
#pragma once

#include <cstddef>
#include <vector>

#include "hecal/handeye/motion.h"
#include "hecal/handeye/problem.h"

namespace hecal::handeye {

void RequireMotions(const std::vector<Motion>& motions, size_t minimum);
void RequireStations(const Problem& problem, size_t minimum);

double TranslationScale(const std::vector<Motion>& motions);
double TranslationScale(const Problem& problem);

}  // namespace hecal::handeye
