// Silencing the libraries' own logs: see library_logs.h.
#include "library_logs.h"

#if defined(HECAL_HAVE_GLOG)
#include <glog/logging.h>
#endif
#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "hecal/hecal.h"
#endif

namespace hecal::cli {

void SilenceLibraryLogs() {
#if defined(HECAL_HAVE_GLOG)
  FLAGS_minloglevel = google::GLOG_FATAL;  // a FATAL check still aborts; nothing else is printed
  FLAGS_stderrthreshold = google::GLOG_FATAL;
#endif
#if defined(HECAL_HAVE_OPENCV_PEERS)
  vision::SilenceOpenCvLog();
#endif
}

}  // namespace hecal::cli
