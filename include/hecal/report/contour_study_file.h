// The result files of `hecal contour study` (docs/contour.md#the-experiments, docs/cli.md): the
// steps of contour::RunContourStudy (contour/contour_study.h) as
//  - CSV: a comment line with the seed and the sample count, then one row per step and pose
//    component: motion,value,component,mc_mean_error,mc_std,ut_mean_error,ut_std,bias
//    (component Tx,Ty,Tz,Rx,Ry,Rz; errors against the true motion in mm and degrees; bias 1 when
//    the bias check flags the component);
//  - the HTML page (kind "contour_study", drawn by web/contour_study.js in the page shell of
//    html_report.h; docs/report.md "The contour study page"): the steps' numbers, and as Plotly.js
//    figures the contour paper's Fig. 3 (mean error ± 2σ against the motion, one panel per pose
//    component, UT solid, Monte Carlo dashed) and Fig. 4 at the step nearest a motion value
//    (every 2×2 block of the pose covariance as 2σ ellipses, UT solid and Monte Carlo dashed,
//    with the kept Monte Carlo poses, ContourStudyOptions::keep_samples, and the 13 sigma
//    points).
// Display units: mm for Tx..Tz, degrees for Rx..Rz (the contour paper's).
#pragma once

#include <array>
#include <nlohmann/json.hpp>
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

// The page data: "motion", "motion_label", the setting (seed, samples, pixel_noise, z0_mm,
// focal_mm, pixel_size_mm), "components" and their "units", "steps" (value; mc_mean, mc_sd,
// ut_mean, ut_sd: the errors per component in display units; bias: 6 flags) and "covariance" at
// NearestStep(steps, at): its value, the MC and UT mean errors, both covariances in display units
// (C_ab scaled by the units of a and b), the kept Monte Carlo poses and the sigma points as
// errors against the truth (rows of 6, display units). `steps` not empty.
nlohmann::json ContourStudyPageData(const contour::ContourStudyOptions& o,
                                    const std::vector<contour::StudyStep>& steps, double at,
                                    const std::string& title);

}  // namespace hecal::report
