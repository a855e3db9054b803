// A job's texts printed: see job_output.h.
#include "job_output.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <ostream>

namespace hecal::cli {

jobs::JobCallbacks PrintingCallbacks(const Io& io) {
  return {[&io](const std::string& text) { io.out << text << std::flush; },
          [&io](const std::string& note) { io.err << "hecal: note: " << note << "\n"; },
          [&io](const std::string& warning) { io.err << "hecal: warning: " << warning << "\n"; }};
}

}  // namespace hecal::cli

#endif  // HECAL_HAVE_OPENCV_PEERS
