// The image thumbnails of a report page as a job step (`hecal report --images DIR`,
// `calibrate --images --report`, `detect --report`; docs/report.md): the first
// report::kMaxThumbnails of the images named, each read from the folder and made a
// report::kThumbnailSide-pixel JPEG (vision/thumbnail.h), on every core (the decoding itself one
// file at a time: vision::ReadGrayImage holds a lock while it captures the codecs' messages).
// Defined with the vision layer only (the report library reads no image); callers built without
// it check HECAL_HAVE_VISION.
//
// Errors (InputError, nothing written by the caller): an image that is not in the folder (named
// with its station id, the folder and `flag`, the command-line flag that gave the folder), and
// ReadGrayImage's refusals of a file (named).
#pragma once

#include <string>
#include <vector>

#include "hecal/report/page_thumbnails.h"

namespace hecal::jobs {

struct ReportImage {
  std::string id;    // station id
  std::string file;  // in the folder, e.g. "im_00.png" or "pose_00/image.png"
};

std::vector<report::Thumbnail> ReadThumbnails(const std::string& folder,
                                              const std::vector<ReportImage>& images,
                                              const std::string& flag);

}  // namespace hecal::jobs
