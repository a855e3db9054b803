// The command line's own voice only: the libraries hecal calls log to the process's standard
// error on their own — Ceres through glog ("W… residual_block.cc… Error in evaluating the
// ResidualBlock"), OpenCV through its logger (imread warnings) — and those lines would break the
// one-line error rule of the CLI (docs/reliability.md). SilenceLibraryLogs raises glog's minimum
// level above ERROR and sets OpenCV's log level to silent (vision/opencv_log.h); the failures
// behind such lines reach the user as hecal's own reasons (a solver's failure, an image that cannot
// be decoded). Safe to call more than once.
#pragma once

namespace hecal::cli {

void SilenceLibraryLogs();

}  // namespace hecal::cli
