// The result files of `hecal contour study` (docs/contour.md#the-experiments, docs/cli.md): the
// steps of contour::RunContourStudy (contour/contour_study.h) as
//  - CSV: a comment line with the seed and the sample count, then one row per step and pose
//    component: motion,value,component,mc_mean_error,mc_std,ut_mean_error,ut_std,bias
//    (component Tx,Ty,Tz,Rx,Ry,Rz; errors against the true motion in mm and degrees; bias 1 when
//    the bias check flags the component);
//  - the contour paper's Fig. 3 (SVG, report/svg_figure.h): mean error ± 2σ against the motion,
//    UT solid, Monte Carlo dashed, one panel per component;
//  - Fig. 4 at the step nearest a motion value: every 2×2 block of the pose covariance as 2σ
//    ellipses (UT solid, Monte Carlo dashed) with the kept Monte Carlo poses
//    (ContourStudyOptions::keep_samples) and the 13 sigma points.
// Display units: mm for Tx..Tz, degrees for Rx..Rz (the contour paper's).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hecal/contour/contour_study.h"

namespace hecal::report {

inline constexpr std::array<const char*, 6> kStudyComponents = {"Tx", "Ty", "Tz", "Rx", "Ry", "Rz"};

// `value` of pose component `component` (mm, rad) in display units (mm, degrees).
double StudyDisplay(int component, double value);

// "tx (mm)" / "rx (deg)".
std::string StudyMotionLabel(contour::StudyMotion motion);

// The step whose motion value is nearest `at` (the first of equals); `steps` not empty.
const contour::StudyStep& NearestStep(const std::vector<contour::StudyStep>& steps, double at);

std::string ContourStudyCsv(const contour::ContourStudyOptions& o,
                            const std::vector<contour::StudyStep>& steps);

// Fig. 3 (SVG).
std::string ContourStudyFigure(const contour::ContourStudyOptions& o,
                               const std::vector<contour::StudyStep>& steps);

// Fig. 4 (SVG) at NearestStep(steps, at).
std::string ContourCovarianceFigure(const contour::ContourStudyOptions& o,
                                    const std::vector<contour::StudyStep>& steps, double at);

}  // namespace hecal::report
