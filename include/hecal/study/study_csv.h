// The study's files (`hecal simulate --output / --summary`): CSV with a header line,
// errors in degrees and millimetres, numbers with 9 significant digits ("nan" for a failed
// trial), so the same seed gives byte-identical files.
//
// Trials (one row per setting × trial × method):
//   setup,stations,noise_on,noise,sigma_mm,sigma_deg,trial,method,status,rotation_error_deg,
//   translation_error_mm,outlier,bound_rotation_deg,bound_translation_mm,nees,message,
//   gross_outliers,rejected_outliers,rejected_good,rotation_error_clean_deg,
//   translation_error_clean_mm
//   status: ok | threw | non-finite; outlier: 0/1 (triangle threshold on the rotation OR the
//   translation errors of that setting and method); bound_*: the trial's first-order bound
//   (study.h); nees: eᵀ Σ⁻¹ e of X with the predicted covariance (nan without --covariance);
//   message: the exception text of a failed trial, double-quoted. gross_outliers: stations whose
//   robot pose was replaced (--outliers); rejected_*: the replaced and the good stations the
//   method rejected (with --reject-outliers); *_clean: the error of the same method on the same
//   data set without the replaced stations (nan without gross outliers).
// Summary (one row per setting × method):
//   setup,stations,noise_on,noise,sigma_mm,sigma_deg,method,trials,failures,outliers,
//   rotation_{median,rmse,p10,p90,max,rmse_inliers}_deg,
//   translation_{median,rmse,p10,p90,max,rmse_inliers}_mm,
//   bound_rotation_rmse_deg,bound_translation_rmse_mm,worst_rotation_over_bound,
//   worst_translation_over_bound,mean_nees,nees_band_low,nees_band_high,coverage_1sigma,
//   coverage_2sigma,sd_ratio_{rx,ry,rz,tx,ty,tz},gross_outliers,outliers_found,good_rejected,
//   trials_all_found,rotation_rmse_clean_deg,translation_rmse_clean_mm
//   Statistics are over the finite trials, outliers included, except *_rmse_inliers (outliers
//   removed, as the thesis reports). bound_*_rmse: RMS over the trials of the per-trial bound.
//   worst_*_over_bound: the largest error / (that trial's bound).
//   Consistency columns (nan without --covariance; uncertainty/consistency.h): the mean NEES
//   of X with its 95% χ² band for 6 dof × trials, the fractions of trials inside the 1σ/2σ
//   ellipsoids (a consistent covariance: 0.683 / 0.954), and predicted / empirical standard
//   deviation per axis of X's tangent error (ω then v). outliers_found: the fraction of replaced
//   stations rejected; good_rejected: the fraction of good stations rejected; trials_all_found:
//   the fraction of trials in which every replaced station was rejected; *_rmse_clean: RMS
//   error without the replaced stations (nan without gross outliers).
// sigma_mm / sigma_deg are the setting's noise parameter as given (for uniform noise, the
// half-width; for systematic, the offset).
#pragma once

#include <string>

#include "hecal/study/study.h"

namespace hecal::study {

std::string TrialsCsv(const StudyResult& result);
std::string SummaryCsv(const StudyResult& result);

// Number formatting shared by the CSV files and the CLI: 9 significant digits, "nan", "inf".
std::string FormatNumber(double value);

}  // namespace hecal::study
