// The page data of `hecal simulate --report` (docs/report.md "The simulate page",
// docs/thesis-study.md): the study's results (study/study.h) as the JSON blob that web/simulate.js
// draws (kind "simulate"; the page shell is html_report.h's FormatHtmlPage).
//
// What it holds, in the units the CLI prints (degrees, millimetres):
//  - "settings": one object per setting (setup, stations, noise_on, noise, sigma_mm, sigma_deg,
//    robot_scale, gross_outliers, a readable "label") with its first-order bound (the RMS of the
//    trial bounds of ml at the truth, study.h: Bound) and one summary per method: failures,
//    outliers, median / RMSE / p10 / p90 / max of X's rotation and translation error, the RMSE
//    without outliers, the worst error over its own trial's bound, and — with a predicted
//    covariance — the consistency (mean NEES and its 95% band, 1σ/2σ coverage, sd ratios per
//    axis; uncertainty/consistency.h), with the model-only one; with gross outliers or
//    rejection, the stations found and the clean reference's RMSE (the table of study_text.h).
//  - "trials": per setting and method the errors of at most kMaxPlottedTrials trials (an even
//    sample in trial order; failed trials have none), for the distributions; "trials_total"
//    and "trials_sampled" say how many there were and whether a sample was taken; the page
//    says so in a note. Every number above uses every trial.
//  - "methods", "trials_per_setting", "seed", "covariance" (the covariance method or "none").
// NaN (a failed or undefined statistic) is written as null.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "hecal/study/study.h"

namespace hecal::report {

constexpr std::size_t kMaxPlottedTrials = 500;

nlohmann::json SimulatePageData(const study::StudyResult& result, const std::string& title);

}  // namespace hecal::report
