// The image files of a folder: see image_files.h.
#include "image_files.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

#include "hecal/core/error.h"

namespace hecal::cli {

namespace fs = std::filesystem;

bool IsImageFile(const fs::path& path) {
  constexpr std::array<std::string_view, 6> kExtensions = {".png", ".jpg", ".jpeg",
                                                           ".bmp", ".tif", ".tiff"};
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::find(kExtensions.begin(), kExtensions.end(), extension) != kExtensions.end();
}

std::vector<fs::path> ListImageFiles(const std::string& dir, const std::string& contents) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) {
    throw InputError(dir, 0, "not a directory, or it does not exist",
                     "give --images the folder that holds " + contents);
  }
  std::vector<fs::path> files;
  for (fs::directory_iterator it(dir, error); !error && it != fs::directory_iterator();
       it.increment(error)) {
    std::error_code status_error;
    if (it->is_regular_file(status_error) && IsImageFile(it->path())) files.push_back(it->path());
  }
  if (error) {
    throw InputError(dir, 0, "cannot list the directory: " + error.message(),
                     "check that it is readable");
  }
  if (files.empty()) {
    throw InputError(dir, 0, "no images (png, jpg, jpeg, bmp, tif, tiff) in the directory",
                     "put " + contents + " there, or give --images the right folder");
  }
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    return a.filename().string() < b.filename().string();
  });
  return files;
}

}  // namespace hecal::cli
