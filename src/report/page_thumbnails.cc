// The image thumbnails of a report page: page_thumbnails.h, docs/report.md.
#include "hecal/report/page_thumbnails.h"

namespace hecal::report {
namespace {

// RFC 4648 §4 base64, with padding.
std::string Base64(const std::string& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t k = 0; k < bytes.size(); k += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - k);
    unsigned value = 0;
    for (size_t j = 0; j < 3; ++j)
      value = (value << 8) | (j < n ? static_cast<unsigned char>(bytes[k + j]) : 0u);
    for (size_t j = 0; j < 4; ++j) out += j <= n ? kAlphabet[(value >> (18 - 6 * j)) & 63u] : '=';
  }
  return out;
}

}  // namespace

nlohmann::json ThumbnailsJson(const std::vector<Thumbnail>& thumbnails, size_t images) {
  nlohmann::json by_id = nlohmann::json::object();
  size_t bytes = 0;
  for (const Thumbnail& t : thumbnails) {
    std::string uri = "data:image/jpeg;base64," + Base64(t.jpeg);
    bytes += uri.size();
    by_id[t.id] = std::move(uri);
  }
  return {{"by_id", by_id}, {"count", thumbnails.size()}, {"images", images}, {"bytes", bytes}};
}

}  // namespace hecal::report
