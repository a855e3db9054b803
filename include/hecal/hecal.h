// hecal's front door: the one header a program, the command line (apps/hecal), the examples and
// the Python module (python/) include. Everything a user runs is a job of hecal::jobs with typed
// options (IsValid names the first bad field) and a typed result; the headers below are that
// layer, the vocabulary its options and results speak (poses, rotations, units, methods, setups,
// errors) and the formatting of its results (report/). Every other header under include/hecal is
// implementation: installed so that these compile, but free to change (docs/architecture.md#layers).
//
// Conventions (docs/conventions.md): T_a_b maps coordinates in frame b to frame a; lengths in
// metres and angles in radians inside the library, files in the units they name; covariances
// are of right perturbations, (rx, ry, rz, tx, ty, tz) per pose. Errors (core/error.h):
// hecal::InputError (a file or option is wrong: source, line, what, fix) and
// hecal::DegenerateError (the data do not determine the unknowns: what cannot be observed).
#pragma once

// Vocabulary: errors and option checks, poses and rotations, units, setups, methods, pose and
// point files, writing files whole.
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/methods.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/euler.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/convention_check.h"
#include "hecal/handeye/problem.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/import.h"
#include "hecal/io/pose_table.h"
#include "hecal/io/units.h"
#include "hecal/io/workspace_file.h"
#include "hecal/pose/pose_method.h"
#include "hecal/version.h"

// The jobs: calibration from poses (in memory or files), target-free; import and conversion of
// pose files; pose from known points; simulation and the benchmark protocol; the contour
// methods; OpenCV's hand–eye functions as drop-ins (the Python module's cv2 drop-in); a
// calibration's HTML report.
#include "hecal/jobs/bench.h"
#include "hecal/jobs/calibration_report.h"
#include "hecal/jobs/contour_jobs.h"
#include "hecal/jobs/global_calibration.h"
#include "hecal/jobs/import.h"
#include "hecal/jobs/opencv_drop_in.h"
#include "hecal/jobs/pivot.h"
#include "hecal/jobs/pivot_study.h"
#include "hecal/jobs/plan.h"
#include "hecal/jobs/plan_study.h"
#include "hecal/jobs/point_pose.h"
#include "hecal/jobs/pose_calibration.h"
#include "hecal/jobs/pose_conversion.h"
#include "hecal/jobs/pose_file_calibration.h"
#include "hecal/jobs/simulate.h"
#include "hecal/jobs/stream_calibration.h"
#include "hecal/jobs/stream_study.h"
#include "hecal/study/study.h"
#include "hecal/study/study_csv.h"
#if defined(HECAL_HAVE_VISION)
// The jobs that read images: calibration from images, detection, pose by any method name
// (OpenCV's PnP too), target-free matches, contour tracking and rendering, OpenCV's hand-eye
// functions as the benchmark's peer; the detect page of the HTML report.
#include "hecal/jobs/contour_rendering.h"
#include "hecal/jobs/contour_tracking.h"
#include "hecal/jobs/detection_report.h"
#include "hecal/jobs/global_matches.h"
#include "hecal/jobs/image_calibration.h"
#include "hecal/jobs/image_folder_calibration.h"
#include "hecal/jobs/image_stream_calibration.h"
#include "hecal/jobs/job_callbacks.h"
#include "hecal/jobs/opencv_bench_peer.h"
#include "hecal/jobs/pose_detection.h"
#include "hecal/jobs/pose_from_points.h"
#include "hecal/vision/opencv_log.h"
#endif

// Results as documents and text: the calibration result file (JSON/YAML) and summary, the
// target-free result, pose estimates, studies and the benchmark, the contour jobs.
#include "hecal/report/bench_file.h"
#include "hecal/report/contour_pose_file.h"
#include "hecal/report/contour_pose_text.h"
#include "hecal/report/contour_study_file.h"
#include "hecal/report/contour_study_text.h"
#include "hecal/report/contour_track_file.h"
#include "hecal/report/contour_track_text.h"
#include "hecal/report/global_page.h"
#include "hecal/report/global_result.h"
#include "hecal/report/global_text.h"
#include "hecal/report/html_report.h"
#include "hecal/report/pivot_file.h"
#include "hecal/report/pivot_text.h"
#include "hecal/report/pose_file.h"
#include "hecal/report/pose_text.h"
#include "hecal/report/report_input.h"
#include "hecal/report/result_file.h"
#include "hecal/report/result_text.h"
#include "hecal/report/simulate_page.h"
#include "hecal/report/study_text.h"
