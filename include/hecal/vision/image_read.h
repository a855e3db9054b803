// One image file read (the image front end, vision/image_set.h; `hecal contour track`), bounded
// and with hecal's own reasons instead of the codecs' (docs/reliability.md):
//   1. the file is read whole with io::ReadFile (a regular file of at most 256 MiB);
//   2. its size is taken from the file header before any pixel is decoded — PNG (IHDR, ISO/IEC
//      15948 §11.2.2), JPEG (the first SOFn segment, ITU-T T.81 §B.2.2), BMP
//      (BITMAPINFOHEADER) and TIFF (tags 256/257 of the first IFD, TIFF 6.0 §8) — and must be
//      at most io::kMaxImagePixels (10^8, io/image_files.h) pixels and at least `min_side` pixels a
//      side; a file whose header is not one of these formats, or is cut short, cannot be decoded;
//   3. a JPEG must hold its end-of-image marker after the start of the scan (ITU-T T.81
//      §B.2.1): libjpeg decodes a file cut short to grey without a word when it reads from
//      memory;
//   4. it is decoded to 8-bit grey by cv::imdecode, one file at a time, with the codecs'
//      messages (libjpeg's "Corrupt JPEG data: …", libpng's errors), which they print on the
//      process's standard error, captured: a JPEG that makes libjpeg complain, and any file the
//      codec cannot decode, is refused with that complaint as the reason, so a truncated or
//      corrupt image never passes as a picture without a target. (libpng's warnings on a PNG
//      that decodes, e.g. an sRGB profile note, are dropped.)
// Sizes are in pixels. Errors: hecal::InputError(path, 0, ...) for each refusal above.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace hecal::vision {

// The smallest side (pixels) of an image searched for a target.
constexpr int kMinDetectionSide = 16;

struct ImageSize {
  int width = 0;
  int height = 0;
};

// The width and height written in the header of a PNG, JPEG, BMP or TIFF file held in `bytes`;
// InputError naming `path` when the header is none of these or is cut short.
ImageSize ImageHeaderSize(const std::string& path, const std::string& bytes);

// The image at `path` as 8-bit grey (see above). `min_side` is the smallest width or height
// accepted (kMinDetectionSide for target detection).
cv::Mat ReadGrayImage(const std::string& path, int min_side);

}  // namespace hecal::vision
