// The image files of a folder, and its stations: see image_files.h.
#include "hecal/io/image_files.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/io/delimited_text.h"

namespace hecal::io {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kImageKinds = "png, jpg, jpeg, bmp, tif, tiff";

bool ByFileName(const fs::path& a, const fs::path& b) {
  return a.filename().string() < b.filename().string();
}

// The entries of `dir` that `keep` accepts, sorted by file name. Throws when `dir` is not a
// directory or cannot be listed.
template <typename Keep>
std::vector<fs::path> Entries(const fs::path& dir, const std::string& contents, Keep keep) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) {
    throw InputError(dir.string(), 0, "not a directory, or it does not exist",
                     "give --images the folder that holds " + contents);
  }
  std::vector<fs::path> entries;
  for (fs::directory_iterator it(dir, error); !error && it != fs::directory_iterator();
       it.increment(error)) {
    if (keep(*it)) entries.push_back(it->path());
  }
  if (error) {
    throw InputError(dir.string(), 0, "cannot list the directory: " + error.message(),
                     "check that it is readable");
  }
  std::sort(entries.begin(), entries.end(), ByFileName);
  return entries;
}

std::vector<fs::path> ImagesIn(const fs::path& dir, const std::string& contents) {
  return Entries(dir, contents, [](const fs::directory_entry& entry) {
    std::error_code error;
    return entry.is_regular_file(error) && IsImageFile(entry.path());
  });
}

std::vector<fs::path> SubFolders(const fs::path& dir, const std::string& contents) {
  return Entries(dir, contents, [](const fs::directory_entry& entry) {
    std::error_code error;
    return entry.is_directory(error) && entry.path().filename().string().rfind('.', 0) != 0;
  });
}

std::string Names(const std::vector<fs::path>& paths) {
  std::string names;
  for (const fs::path& path : paths) {
    if (!names.empty()) names += ", ";
    names += path.filename().string();
  }
  return names;
}

}  // namespace

bool IsImageFile(const fs::path& path) {
  constexpr std::array<std::string_view, 6> kExtensions = {".png", ".jpg", ".jpeg",
                                                           ".bmp", ".tif", ".tiff"};
  const std::string extension = Lowercase(path.extension().string());
  return std::find(kExtensions.begin(), kExtensions.end(), extension) != kExtensions.end();
}

std::vector<fs::path> ListImageFiles(const std::string& dir, const std::string& contents) {
  std::vector<fs::path> files = ImagesIn(dir, contents);
  if (files.empty()) {
    throw InputError(dir, 0, "no images (" + std::string(kImageKinds) + ") in the directory",
                     "put " + contents + " there, or give --images the right folder");
  }
  return files;
}

StationImages ListStationImages(const std::string& dir, const std::string& contents) {
  StationImages result;
  const std::vector<fs::path> files = ImagesIn(dir, contents);
  const std::vector<fs::path> folders = SubFolders(dir, contents);
  if (!files.empty()) {
    for (const fs::path& file : files) {
      result.stations.push_back({file.stem().string(), file, file.filename().string()});
    }
    if (!folders.empty()) {
      result.note = dir + " holds " + std::to_string(files.size()) + " image(s) and " +
                    std::to_string(folders.size()) +
                    " sub-folder(s): using the images, one station each; the sub-folders (" +
                    Names(folders) + ") are left out";
    }
    return result;
  }
  if (folders.empty()) {
    throw InputError(dir, 0,
                     "no images (" + std::string(kImageKinds) +
                         ") in the directory, and no sub-folders with one each",
                     "put " + contents +
                         " there (one per station), or one sub-folder per station with its "
                         "image; or give --images the right folder");
  }
  result.sub_folders = true;
  for (const fs::path& folder : folders) {
    const std::vector<fs::path> images = ImagesIn(folder, contents);
    const std::string name = folder.filename().string();
    if (images.empty()) {
      throw InputError(
          folder.string(), 0,
          "this station's sub-folder holds no image (" + std::string(kImageKinds) +
              "); with no image directly in " + dir + ", each sub-folder is one station",
          "put the station's image in " + name + ", or move the sub-folder out of " + dir);
    }
    if (images.size() > 1) {
      throw InputError(folder.string(), 0,
                       "this station's sub-folder holds " + std::to_string(images.size()) +
                           " images (" + Names(images) + "); it must hold exactly one",
                       "keep one image in " + name +
                           " (move the others out), or put one image per station directly in " +
                           dir);
    }
    result.stations.push_back(
        {name, images.front(), name + "/" + images.front().filename().string()});
  }
  return result;
}

}  // namespace hecal::io
