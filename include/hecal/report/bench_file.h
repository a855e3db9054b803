// The JSON of `hecal bench --json` (docs/bench.md): one array, one object per row of
// study::RunBench (study/bench.h), in its order:
//   {"impl": "hecal" | peer name, "method": "park-martin", "start": null | "closed-form" | "good",
//    "stations": 50, "us_per_solve": 12.3, "rotation_error_deg": …, "translation_error": …,
//    "translation_unit": "m", "failures": 0, "datasets": 10, "seed": 1}
// rotation_error_deg / translation_error: RMS over the data sets of the error of X (degrees;
// metres), null when no solve returned a finite pose. Keys are written in alphabetical order.
#pragma once

#include <string>

#include "hecal/study/bench.h"

namespace hecal::report {

// The document, pretty-printed (two-space indent) with a final newline.
std::string BenchJson(const study::BenchResult& result);

}  // namespace hecal::report
