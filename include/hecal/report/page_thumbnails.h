// The image thumbnails of a report page (docs/report.md, "From images" and "The detect page"):
// small JPEGs (made by the jobs layer, vision/thumbnail.h: the report library reads no image)
// put into the page data as data URIs, so that a click on an image's entry shows the image under
// its detected points. At most kMaxThumbnails per page, the images' first in order; the page
// states how many there are, of how many images, and their size in bytes.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hecal::report {

constexpr int kThumbnailSide = 320;     // the longer side of a thumbnail (px)
constexpr size_t kMaxThumbnails = 200;  // per page (~10 kB each: ~2 MB)

struct Thumbnail {
  std::string id;    // the image's station id
  std::string jpeg;  // the JPEG file's bytes
};

// {"by_id": {id: "data:image/jpeg;base64,..."}, "count", "images": `images` (how many images
// the page shows, with or without a thumbnail), "bytes" (of the data URIs)}.
nlohmann::json ThumbnailsJson(const std::vector<Thumbnail>& thumbnails, size_t images);

}  // namespace hecal::report
