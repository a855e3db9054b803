// Contour sequences as image files (`hecal contour track`, `hecal contour render`;
// docs/contour.md): the contour layer's jobs (contour/sequence.h) fed with, and turned into,
// 8-bit grey images.
//
// TrackImageSequence: every *.png, *.jpg, *.jpeg, *.bmp, *.tif, *.tiff in the folder (not
// recursive, io/image_files.h), sorted by file name, read as 8-bit grey (image_read.h, at least
// io::kMinImageSide pixels a side), all of one size, tracked in order; the first is the template
// view. Grey levels are 0 … 255, pixel centres at integer coordinates (contour/gray_image.h).
// EncodePng: a rendered frame as PNG bytes; the values must be whole grey levels in 0 … 255
// (render with RenderOptions::quantize, contour/render.h).
//
// Errors (hecal::InputError): a missing folder or one without images; an unreadable image
// (image_read.h: larger than 10^8 pixels, smaller than 8 × 8, cut short or corrupt); images of
// different sizes (naming the image and both sizes); a PNG that OpenCV cannot encode. Those of
// contour::SequenceTracker::Track pass through.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hecal/contour/gray_image.h"
#include "hecal/contour/sequence.h"

namespace hecal::vision {

using contour::TrackedImage;  // contour/sequence.h

// Tracks the images of `dir` with `tracker`, handing every frame to `on_frame` (may be empty)
// as soon as it is tracked.
std::vector<TrackedImage> TrackImageSequence(
    const std::string& dir, contour::SequenceTracker* tracker,
    const std::function<void(const TrackedImage&)>& on_frame = {});

// The image as an 8-bit grey PNG file's bytes; `path` names it in errors.
std::string EncodePng(const contour::GrayImage& image, const std::string& path);

}  // namespace hecal::vision
