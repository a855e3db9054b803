// The image files of a folder, for every command that reads an image folder (`detect`,
// `calibrate --images`, `contour track`): every *.png, *.jpg, *.jpeg, *.bmp, *.tif, *.tiff
// (extension case-insensitive, not recursive), sorted by file name. No OpenCV: listing is not
// reading.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hecal::cli {

bool IsImageFile(const std::filesystem::path& path);

// Throws hecal::InputError (source: the folder) when it is missing, unreadable or has no image;
// `contents` names what the folder should hold for the fix, e.g. "the target images".
std::vector<std::filesystem::path> ListImageFiles(const std::string& dir,
                                                  const std::string& contents);

}  // namespace hecal::cli
