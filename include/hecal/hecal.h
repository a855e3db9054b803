// hecal's front door: the one header a program, the command line (apps/hecal) and the Python
// module (python/) include. Everything a user runs is a job of hecal::jobs with typed options
// (IsValid names the first bad field) and a typed result; the headers below are that layer and
// the vocabulary its options and results speak (poses, units, methods, result documents and
// their formatting). Every other header under include/hecal is implementation: installed, so
// that the ones below compile, but free to change between releases (docs/README.md#layers).
//
// Conventions (docs/conventions.md): T_a_b maps coordinates in frame b to frame a; lengths in
// metres and angles in radians inside the library, files in the units they name; covariances
// are of right perturbations, (rx, ry, rz, tx, ty, tz) per pose. Errors: hecal::InputError (a
// file or option is wrong: source, line, what, fix) and hecal::DegenerateError (the data do not
// determine the unknowns: what cannot be observed), core/error.h.
#pragma once

// Vocabulary: errors, poses and rotations, units, methods, setups.
#include "hecal/core/error.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/methods.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/euler.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "hecal/io/pose_table.h"
#include "hecal/io/units.h"
#include "hecal/version.h"

// The jobs: calibration from poses (in memory or files) and from images, detection, pose from
// points, contours; OpenCV's hand–eye functions as drop-ins.
#include "hecal/jobs/opencv_drop_in.h"
#include "hecal/jobs/pose_calibration.h"
#include "hecal/jobs/pose_file_calibration.h"
#if defined(HECAL_HAVE_VISION)
#include "hecal/jobs/contour_rendering.h"
#include "hecal/jobs/contour_tracking.h"
#include "hecal/jobs/global_matches.h"
#include "hecal/jobs/image_folder_calibration.h"
#include "hecal/jobs/opencv_bench_peer.h"
#include "hecal/jobs/pose_detection.h"
#include "hecal/jobs/pose_from_points.h"
#endif

// The thesis study over sweeps (`hecal simulate`) and its CSV files.
#include "hecal/study/simulate.h"
#include "hecal/study/study_csv.h"

// Results as documents: the result file (JSON/YAML) and the printed summary.
#include "hecal/report/result_file.h"
#include "hecal/report/result_text.h"
