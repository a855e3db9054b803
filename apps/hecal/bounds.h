// The command line's own rules (README "Reliability"): the syntax of a value, read in one place
// per kind. What a value may be — its range, a fact of the library — is the options' IsValid
// (core/options_check.h; thread counts core/limits.h, noise levels estimation/pose_sigma.h, Monte
// Carlo samples estimation/covariance_method.h, pixel noise estimation/reprojection_refinement.h,
// the jobs' own options: study/simulate.h, study/bench.h, report/point_pose.h,
// contour/contour_study.h, contour/sequence.h); the CLI shows the flag of the field it names
// (field_flags.h). Every rule below fails with a hecal::InputError naming the flag and the text
// (exit 2), before any work.
//
//   kind of value          flags                             the CLI's rule
//   whole number           --threads, --trials, --datasets,  decimal digits, an optional leading
//                          --steps, --samples, --frames,     '-' (spaces around are ignored); the
//                          --covariance-samples,             value must fit the field's type
//                          --matches-per-motion, --max-cubes (AddWholeNumber)
//   seed                   --seed                            decimal digits, 0 … 2^64 − 1, no sign
//                                                            (AddWholeNumber)
//   whole-number list      --stations, --outliers            comma separated whole numbers, no
//                                                            empty item (AddWholeNumberList)
//   noise level            --robot-sigma, --camera-sigma     MM,DEG: two finite numbers
//                          simulate's and bench's --sigma    N or MM/DEG (simulate: a comma list)
//                                                            (ParseNoiseLevel, list_flags.h)
//   real number            --focal, --z0, --min-time, …      CLI11's reading of a double
//   pixel noise            --pixel-sigma                     one finite number (none: the
//                                                            default or, from images, estimated;
//                                                            ParsePixelSigma, calibrate.h)
//
// CLI11 2.1.2 reads integers with strtoll base 0 ("010" is 8, "0x10" 16) and unsigned ones with
// strtoull ("-1" becomes 2^64 − 1), so every whole-number flag is bound through AddWholeNumber:
// the text is read as a decimal number of the field's type and handed to CLI11 as its plain
// decimal.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace hecal::cli {

// Binds `flag` to `value` (int, std::int64_t or std::uint64_t) through the whole-number rule
// above; returns the option for further settings (default text, group).
template <class T>
CLI::Option* AddWholeNumber(CLI::App& command, const std::string& flag, T& value,
                            const std::string& help);

// Binds `flag` to `values`: one argument, comma separated whole numbers (SplitList, list_flags.h;
// the rule above per item).
CLI::Option* AddWholeNumberList(CLI::App& command, const std::string& flag,
                                std::vector<int>& values, const std::string& help);

}  // namespace hecal::cli
