// The image front end as the CLI runs it (`hecal detect`, `hecal calibrate --images`): the job
// vision::DetectImageSet (hecal/vision/image_set.h) with its stages printed as they finish (the
// lines on stdout and stderr: docs/cli.md#hecal-detect).
#pragma once

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <string>

#include "cli.h"
#include "hecal/vision/image_set.h"

namespace hecal::cli {

using vision::ImageRecord;
using vision::ImageSet;
using vision::ImageUse;

// vision::DetectImageSet, printing on `io`; `command` names the caller in the first line
// ("hecal detect").
ImageSet DetectImageSet(const vision::ImageSetOptions& options, const std::string& command,
                        const Io& io);

}  // namespace hecal::cli

#endif  // HECAL_HAVE_OPENCV_PEERS
