// The calibration result as readable text (what `hecal calibrate` prints; docs/cli.md), beside
// the result file of result_file.h.
//
// Summary of one result: the method, setup and station count; X and Z as 3×4 matrices
// [R | t] with their rotation (angle in degrees about the axis) and translation in the
// document's unit; the covariance method and the 1σ of X and Z per axis (rotation in degrees,
// translation in millimetres whatever the unit), each followed by the 1σ of its translation
// along its parent frame's axes, the axes the translation is printed in (translation_sigma.h);
// the residual RMS; one line per station used (rotation in degrees, translation in the unit,
// whitened residual, "> 3σ" flags) — every station up to 200, above that the 20 largest
// whitened residuals — then the rejected stations and the warnings.
//
// Comparison (`--method all`): one line per method with X's translation, the residual RMS, the
// difference from ml (rotation angle in degrees, translation distance) when ml is among the
// results, and the predicted RMS error of X (the square root of the trace of its rotation and
// translation covariance blocks, degrees and millimetres), then the methods that refused.
//
// From images (`--images`, document.images set): how far the joint reprojection refinement moved
// X from the pose-level result (rotation angle in degrees, translation distance in the unit), the
// summary, the intrinsics before → after ± 1σ when they were refined (fx, fy, cx, cy to 7
// significant digits, the distortion to 5), then the reprojection RMS over every point with the
// pixel sigma (given or estimated) and one row per used image: its RMS in px and a "> 3σ" flag.
//
// From streams (`--streams`, document.streams set): the samples of each stream, which one gave
// the stations and how many each rule dropped (docs/streams.md), and the time offset in
// milliseconds with its 1σ, the coarse correlation's value, or "given".
#pragma once

#include <ostream>

#include "hecal/estimation/calibrate.h"
#include "hecal/pose/camera_model.h"
#include "hecal/report/result_file.h"

namespace hecal::report {

// `result` is one of document.results (its station ids: UsedStationIds(document)).
void PrintResultSummary(std::ostream& out, const ResultDocument& document,
                        const estimation::CalibrationResult& result);

// Starts with a blank line.
void PrintMethodComparison(std::ostream& out, const ResultDocument& document);

// Starts with a blank line. `camera_before`: the intrinsics the refinement started from.
void PrintImageResultSummary(std::ostream& out, const ResultDocument& document,
                             const pose::CameraModel& camera_before);

// Starts with a blank line; nothing when document.streams is empty.
void PrintStreamSummary(std::ostream& out, const ResultDocument& document);

}  // namespace hecal::report
