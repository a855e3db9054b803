// The summary `hecal pivot` prints (docs/pivot.md#the-command): the tip in the flange frame and
// the pivot in the base frame in millimetres with their 1σ, the RMS residual, the noise used, the
// stations used and flagged, then the warnings.
#pragma once

#include <ostream>

#include "hecal/report/pivot_file.h"

namespace hecal::report {

void PrintPivotSummary(std::ostream& out, const PivotDocument& document);

}  // namespace hecal::report
