// OpenCV's own log (imread and decoder warnings printed to standard error) switched off. A program
// with a one-line error rule, such as the hecal command line (docs/reliability.md), calls this
// once at start; the failures behind such lines still reach it as exceptions or empty images that
// the vision layer turns into its own reasons. Safe to call more than once.
#pragma once

namespace hecal::vision {

void SilenceOpenCvLog();

}  // namespace hecal::vision
