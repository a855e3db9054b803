// Outlier removal among Monte-Carlo trial results with the triangle threshold, as in the thesis
// (docs/thesis-study.md; the thesis §5.2): build a histogram of the errors, smooth it with a moving
// average, draw a line from the histogram's peak to its far end, and put the threshold at the bin
// of maximum distance below that line (Zack, Rogers & Latt, "Automatic measurement of sister
// chromatid exchange frequency", J. Histochem. Cytochem. 25(7), 1977). Values in bins beyond the
// threshold bin are outliers.
//
// Choices (the thesis does not state them). They were tuned on simulated error samples of 200:
// Maxwell-distributed errors (the rotation-error angle under isotropic noise, the thesis' "no
// outliers" regime), scale mixtures of them (data sets of varying conditioning, as real solver
// errors are), and both with 5–10% of results 10–300× off. With these choices a clean sample
// of 200 gets on average < 0.1 marked (at most 3 in 200 samples), while 99% of the results
// 10–100× off and all of those ≥ 30× off are caught.
//  - Log scale: the histogram is over log10 of the values. The thesis calls outliers results
//    "one, two or even three orders of magnitude larger than expected"; on a log axis that is a
//    fixed distance whatever the noise level. (On a linear axis the triangle cuts 2–15% of a
//    clean sample.) Values ≤ 0 are binned with the smallest positive value.
//  - Floor: values below `floor` are binned at the floor, so they are never outliers and the
//    spread of pure rounding noise (noise-free errors of 1e-16 … 1e-12) does not make a
//    histogram of its own; the study uses 1e-9 rad and 1e-9 m.
//  - Bins: ceil(sqrt(n)) clamped to [5, 15] equal-width bins between the smallest and the
//    largest (floored) value — 15 for the thesis' 200 trials — followed by 2 empty bins: the
//    axis continues past the largest value, so the far end of the line is empty histogram.
//  - Smoothing: centred moving average over 3 bins, truncated at the ends (the empty bins take
//    part, so the last data bin is smoothed like every other).
//  - The line runs from the peak (the first maximum of the smoothed histogram) to the last,
//    farthest bin of the extended histogram; the threshold bin maximises the distance below it.
//  - Knee height: the threshold is used only where the smoothed histogram has fallen to at
//    most 10% of its peak. A knee higher up is the shoulder of a unimodal bulk (on a log axis
//    error distributions are nearly symmetric), not the start of a tail.
//  - Nothing is marked when there are fewer than 3 finite values, all are equal, no bin lies
//    below the line, or the threshold falls in the last data bin or beyond.
// Non-finite values are not binned and are never marked (callers count them as failures).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hecal::sim {

// Centred moving average of `window` bins (odd, ≥ 1); at the ends the window is truncated to
// the bins that exist, so a flat histogram stays flat.
std::vector<double> MovingAverage(std::span<const double> histogram, int window);

// Zack's triangle on a (smoothed) histogram: the peak p is the first maximum; the line runs from
// (p, h[p]) to the farthest bin (e, h[e]), e = h.size() − 1. Returns the index of the bin in
// (p, e) with the largest distance below the line (the first one on ties), or nullopt when no
// bin strictly between lies below it.
std::optional<int> TriangleThresholdBin(std::span<const double> histogram);

struct TriangleThresholdOptions {
  int min_bins = 5;          // at least 1
  int max_bins = 15;         // at least min_bins
  int padding_bins = 2;      // empty bins appended past the largest value (0 or more)
  int smoothing_window = 3;  // odd, at least 1
  bool log_scale = true;
  double floor = 0.0;          // values below are binned at the floor (see above); finite
  double knee_fraction = 0.1;  // the threshold bin's height must be ≤ this × the peak's; (0, 1]

  // core/options_check.h: false naming the field outside the range noted beside it.
  bool IsValid(std::string* why) const;
};

struct TriangleThresholdResult {
  // Values strictly above `threshold` are outliers; +infinity when there are none.
  double threshold = 0.0;
  std::vector<bool> outlier;  // one per input value
  int outlier_count = 0;
};

// Throws hecal::InputError when !options.IsValid.
TriangleThresholdResult TriangleThreshold(std::span<const double> values,
                                          const TriangleThresholdOptions& options = {});

}  // namespace hecal::sim
