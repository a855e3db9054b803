// The translation step shared by every rotation-then-translation solver (Tsai–Lenz eq. 16,
// Park–Martin, Horaud–Dornaika, Chou–Kamel, Shiu–Ahmad): with R_X known, each motion gives
//        (R_Aij − I) · t_X = R_X · t_Bij − t_Aij,
// solved in least squares over all motions by accumulating the 3×3 normal equations.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "hecal/handeye/motion.h"
#include "hecal/handeye/planar.h"

namespace hecal::handeye {

// Throws DegenerateError when the normal matrix is singular (all rotation axes parallel).
Eigen::Vector3d SolveTranslation(const std::vector<Motion>& motions, const Eigen::Matrix3d& R_X);

// The same with one coordinate of t_X given (planar robots, planar.h): least squares subject to
// t_X(fix.axis) = fix.value. Throws DegenerateError when that does not make the solution unique.
Eigen::Vector3d SolveTranslation(const std::vector<Motion>& motions, const Eigen::Matrix3d& R_X,
                                 const TranslationFix& fix);

}  // namespace hecal::handeye
