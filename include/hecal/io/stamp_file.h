// Time stamps of images (`hecal calibrate --streams --images DIR`, docs/streams.md#images-as-the-
// camera-stream): a sidecar CSV, or the image file names themselves.
//
// Sidecar: a header with an image column (`image`, `file` or `id`) and a `stamp` column (seconds,
// any epoch; integer nanoseconds above 1e14 are converted by the stream reader), then one row
// per image; the image is matched by its file stem (folders and extension dropped), so
// `im_01.png`, `images/im_01.png` and `im_01` all name the same image. '#' lines and blank lines
// are skipped; separators as in pose tables (comma, or whitespace).
// File names: an image whose stem is one number (`1634567890.123456.png`, `1634567890123456789.png`)
// is stamped by it.
// Errors are hecal::InputError naming the file and line (or the image) and the fix.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace hecal::io {

// stem → stamp.
std::map<std::string, double> ReadStampFile(const std::string& path);
std::map<std::string, double> ParseStampFile(std::string_view text, const std::string& source);

// The stamp a file name carries (its stem is one finite number); InputError naming the image
// otherwise.
double StampFromFileName(const std::string& stem);

}  // namespace hecal::io
