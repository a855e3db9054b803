// The texts of a library job printed as the CLI prints them (jobs/job_callbacks.h): progress on
// standard output as it comes (flushed, so a long detection shows its stages), notes and warnings
// on standard error as "hecal: note: …" and "hecal: warning: …", one line each.
#pragma once

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli {

jobs::JobCallbacks PrintingCallbacks(const Io& io);

}  // namespace hecal::cli

#endif  // HECAL_HAVE_OPENCV_PEERS
