// The benchmark job in the front door (`hecal bench`, docs/bench.md): hecal's methods, and a peer
// when given (OpenCV's hand–eye functions: jobs::OpenCvBenchPeer, opencv_bench_peer.h), timed and
// scored on identical synthetic data sets. The job is the study protocol's own RunBench
// (study/bench.h), which bench/handeye_bench.cc shares, and its result is what
// report/bench_file.h and report/study_text.h format, so it stays there and is offered here by
// name.
#pragma once

#include "hecal/study/bench.h"

namespace hecal::jobs {

using study::BenchOptions;
using study::BenchPeer;
using study::BenchResult;
using study::RunBench;

}  // namespace hecal::jobs
