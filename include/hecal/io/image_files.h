// The image files of a folder, for every job that reads an image folder (the image front end of
// vision/image_set.h, `hecal contour track`): every *.png, *.jpg, *.jpeg, *.bmp, *.tif, *.tiff
// (extension case-insensitive), sorted by file name. No OpenCV: listing is not reading.
//
// Stations (`detect`, `calibrate --images`; ListStationImages) come in one of two layouts:
//   DIR/im_00.png, DIR/im_01.png, ...       one image per station, station id = the file stem;
//   DIR/pose_00/image.png, DIR/pose_01/...  one sub-folder per station (what many capture tools
//                                           write, with the robot pose beside the image), station
//                                           id = the sub-folder's name.
// The sub-folder layout is used only when DIR holds no image itself; when it holds both, the
// top-level images win and a note names the sub-folders left out. Each sub-folder must hold
// exactly one image (other files, e.g. a pose YAML, are ignored; only one level is searched);
// sub-folders whose name starts with '.' (.git, .thumbnails) are skipped. Stations are sorted by
// file name, or by sub-folder name: the order robot rows pair with when they are not paired by
// id.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "hecal/core/limits.h"

namespace hecal::io {

// The image size bounds (core/limits.h).
using hecal::kMaxImagePixels;
using hecal::kMinImageSide;

bool IsImageFile(const std::filesystem::path& path);

// The image files directly in `dir`. Throws hecal::InputError (source: the folder) when it is
// missing, unreadable or has no image; `contents` names what the folder should hold for the fix,
// e.g. "the target images".
std::vector<std::filesystem::path> ListImageFiles(const std::string& dir,
                                                  const std::string& contents);

struct StationImage {
  std::string id;  // the file stem, or the sub-folder's name
  std::filesystem::path path;
  std::string name;  // for reports: "im_00.png", or "pose_00/image.png"
};

struct StationImages {
  std::vector<StationImage> stations;  // sorted by name (see above)
  bool sub_folders = false;            // one sub-folder per station
  std::string note;                    // when top-level images hid sub-folders: which were left out
};

// The stations of `dir` (see above). Throws hecal::InputError naming the folder when it is
// missing or unreadable, or holds neither images nor sub-folders with images; naming the
// sub-folder when one holds no image or more than one (the images listed).
StationImages ListStationImages(const std::string& dir, const std::string& contents);

}  // namespace hecal::io
