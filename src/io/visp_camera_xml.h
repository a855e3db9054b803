// Internal: ViSP's camera XML (what vpXmlParserCamera::save writes, ViSP
// modules/core/src/camera/vpXmlParserCamera.cpp) → pose::CameraModel. io::ReadCameraFile
// (camera_file.h) calls it for files that start with '<'.
//
// Layout (element names exactly as ViSP's LABEL_XML_* constants; comments anywhere):
//   <?xml version="1.0"?>
//   <root>
//     <camera>                                   one or more
//       <name>Camera</name>                      optional
//       <image_width>640</image_width>           optional, with image_height (pixels)
//       <image_height>480</image_height>
//       <subsampling_width>, <subsampling_height>, <full_width>, <full_height>   optional, unused:
//                                                the intrinsics are for image_width × image_height
//       <model>                                  one per projection model
//         <type>perspectiveProjWithoutDistortion</type>
//         <px>..</px> <py>..</py> <u0>..</u0> <v0>..</v0>
//       </model>
//       <model>
//         <type>perspectiveProjWithDistortion</type>
//         <px>..</px> <py>..</py> <u0>..</u0> <v0>..</v0> <kud>..</kud> <kdu>..</kdu>
//       </model>
//       <additional_information>..</additional_information>   optional, ignored
//     </camera>
//   </root>
//
// Meaning (vpCameraParameters; vpMeterPixelConversion::convertPointWithDistortion): px, py are
// the focal lengths in pixels, (u0, v0) the principal point, and a point with normalised,
// undistorted coordinates (x, y), r² = x² + y², is seen at
//   u = u0 + px·x·(1 + kud·r²),   v = v0 + py·y·(1 + kud·r²).
// That is OpenCV's plumb_bob with fx = px, fy = py, cx = u0, cy = v0, k1 = kud and
// k2 = p1 = p2 = k3 = 0 — the conversion ViSP itself uses (tutorial/bridge/opencv/
// tutorial-bridge-opencv-camera-param.cpp: K = [px 0 u0; 0 py v0; 0 0 1], D = (kud, 0, 0, 0)).
// kdu is the coefficient of ViSP's approximate inverse map (pixels → normalised coordinates,
// vpPixelMeterConversion) and is not used; hecal undistorts by inverting the kud model.
//
// Choice: the model with distortion when the camera has it (a note names it and its kud),
// otherwise the model without distortion (a note says "read as no distortion"). A file with
// several <camera> entries is an error listing their names and sizes, unless every entry reads
// to the same camera. Kannala–Brandt models (ProjWithKannalaBrandtDistortion) and unknown model
// types are errors, as are unknown elements, a model element given twice or missing, a value
// that is not a number, image sizes that are not whole numbers ≥ 1 or only one of them, and a
// kud that is not finite. XML syntax is read with tinyxml2 (Debian's libtinyxml2-dev, private to
// hecal_io); its errors give the line. The focal length and principal point checks of
// camera_file.h (fx, fy > 0, finite cx, cy) are made by ReadCameraFile with the lines returned
// here, as for the YAML layouts.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "hecal/io/camera_file.h"

namespace hecal::io::internal {

struct VispCameraXml {
  CameraFile file;
  std::array<int, 4> lines = {0, 0, 0, 0};  // lines of px, py, u0, v0 (fx, fy, cx, cy)
};

VispCameraXml ParseVispCameraXml(std::string_view text, const std::string& source);

}  // namespace hecal::io::internal
