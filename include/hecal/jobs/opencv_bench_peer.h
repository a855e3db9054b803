// OpenCV 4.6's hand–eye functions as the peer of the benchmark protocol (study/bench.h,
// docs/bench.md): the one adapter that `hecal bench` and bench/handeye_bench.cc time against
// hecal's solvers on identical data sets.
//
// A method has a peer when it is a closed form that OpenCV implements (peers/opencv_handeye.h:
// tsai-lenz, park-martin, horaud, andreff, daniilidis, shah, li); strobl, ml and the closed forms
// OpenCV lacks have none. For such a method, the peer's `prepare` converts every data set once to
// OpenCV's inputs (peers::PrepareOpenCvInput, outside any timing) and returns a solver that runs
// OpenCV's function on data set i and returns its X (frames as handeye/problem.h defines them for
// the data's setup, metres). calibrateHandEye's Z is not computed (the bench times the solve of X
// only). What OpenCV returns is returned as it is (possibly non-finite), and cv::Exception passes
// through (the protocol counts both as failures).
#pragma once

#include "hecal/estimation/methods.h"
#include "hecal/study/bench.h"

namespace hecal::jobs {

// True when `method` has an OpenCV peer (above).
bool HasOpenCvBenchPeer(estimation::Method method);

// The peer named "opencv" (above).
study::BenchPeer OpenCvBenchPeer();

}  // namespace hecal::jobs
