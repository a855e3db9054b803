// The contour study as readable text (what `hecal contour study` prints;
// docs/cli.md#hecal-contour-study, docs/contour.md#the-experiments), beside its CSV and figures
// (contour_study_file.h).
//
// Lines: the setting (motion, Z0 and f in mm, f in px, the pixel σ, the control points, the Monte
// Carlo samples and seed); a legend; per step the motion's value (2 decimals) and per pose
// component (Tx … Rz, in mm and degrees, 4 decimals) the Monte Carlo and UT mean error ± sd
// against the true motion, the ratio UT sd / MC sd (3 decimals) and "*" where the bias check
// flags it, then the failed Monte Carlo samples if any; last, over every pair of components, the
// Monte Carlo correlation of largest magnitude over the steps when it is 0.3 or more (2 decimals).
#pragma once

#include <ostream>
#include <vector>

#include "hecal/contour/contour_study.h"

namespace hecal::report {

void PrintContourStudy(std::ostream& out, const contour::ContourStudyOptions& o,
                       const std::vector<contour::StudyStep>& steps);

}  // namespace hecal::report
