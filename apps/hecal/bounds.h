// The bounds of the command line (README "Reliability"): every number that reaches an
// allocation or a loop — threads, samples, stations, trials, data sets, steps, frames, image
// sizes, noise levels, seeds — is checked against its range before any work, and a value outside
// it is a hecal::InputError naming the flag, the value and the range (exit 2). Where a range is a
// fact of the library it is the library's (the options' IsValid, core/options_check.h: thread
// counts core/limits.h, noise levels estimation/pose_sigma.h, Monte Carlo samples
// estimation/covariance_method.h, pixel noise estimation/reprojection_refinement.h) and the
// calibrate, detect and global flags are checked there only; the rest are the CLI's. The ranges are
// wide enough for every study in this repository and small enough that no flag alone can ask for
// more memory than a workstation has (the largest: 10^5 Monte Carlo samples of two poses, 10^6
// trial rows of `hecal simulate`, 10^8 pixels per image).
//
//   --threads                     0 … 256 (0 = every core)
//   --seed                        0 … 2^64 − 1, a whole decimal number (no sign, no exponent)
//   --covariance-samples          2 … 100000 (calibrate)
//   simulate, bench, pose         study::SimulateOptions::IsValid, study::BenchOptions::IsValid,
//                                 report::PointPoseOptions::IsValid (study/simulate.h,
//                                 study/bench.h, report/point_pose.h)
//   noise levels                  0 … 1000 mm and 0 … 180 deg (--robot-sigma, --camera-sigma)
//   pixel noise                   --pixel-sigma, --measurement-sigma > 0 … 100 px
//   contour study                 contour::ContourStudyOptions::IsValid (contour/contour_study.h)
//   contour track, render         contour::SequenceTrackingOptions::IsValid,
//                                 contour::SequenceRenderOptions::IsValid (contour/sequence.h)
//   images read                   at most 10^8 pixels (checked in the file header before
//                                 decoding), at least 16 × 16 for detection
//                                 (io/image_files.h, vision/image_read.h)
#pragma once

#include <cstdint>
#include <string>

#include "hecal/core/limits.h"
#include "hecal/estimation/covariance_method.h"
#include "hecal/estimation/pose_sigma.h"
#include "hecal/estimation/reprojection_refinement.h"

namespace hecal::cli {

using estimation::kMaxCovarianceSamples;
constexpr double kMaxSigmaMm = estimation::kMaxSigmaTranslation * 1000.0;
constexpr double kMaxSigmaDeg = 180.0;  // estimation::kMaxSigmaRotation in degrees

// A whole number in [min, max] written in decimal ("12", "-3"); InputError with the range
// otherwise. `what` says what the number is, for the fix ("the number of trials").
std::int64_t ParseInteger(const std::string& flag, const std::string& text, std::int64_t min,
                          std::int64_t max, const std::string& what);

// ParseInteger for an int-sized range.
int ParseInt(const std::string& flag, const std::string& text, int min, int max,
             const std::string& what);

// --threads: 0 … kMaxThreads.
int ParseThreads(const std::string& flag, const std::string& text);
// The same range for a thread count CLI11 has parsed (the library's rule, ThreadCountValid in
// core/options_check.h); returns `threads`.
int CheckThreads(const std::string& flag, int threads);

// --seed: 0 … 2^64 − 1.
std::uint64_t ParseSeed(const std::string& flag, const std::string& text);

// A noise level per axis: millimetres in [0, kMaxSigmaMm], degrees in [0, kMaxSigmaDeg].
void CheckNoiseLevel(const std::string& flag, double mm, double deg);

}  // namespace hecal::cli
