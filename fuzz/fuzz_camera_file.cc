// libFuzzer target for the camera file readers (io/camera_file.h: hecal's YAML, OpenCV
// FileStorage, ROS camera_info and ViSP's XML, told apart by content). Any exception other than
// hecal::InputError and any crash is a finding; an accepted camera must have finite, positive
// focal lengths and finite coefficients, and write back (FormatCameraYaml) to a file that reads
// to the same model.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/io/camera_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  hecal::io::CameraFile file;
  try {
    file = hecal::io::ParseCameraFile(text, "camera.yaml");
  } catch (const hecal::InputError&) {
    return 0;
  }
  const hecal::pose::CameraModel& c = file.camera;
  if (!(c.fx > 0.0) || !(c.fy > 0.0) || !std::isfinite(c.fx) || !std::isfinite(c.fy) ||
      !std::isfinite(c.cx) || !std::isfinite(c.cy)) {
    std::abort();
  }
  for (double k : c.distortion)
    if (!std::isfinite(k)) std::abort();
  const std::string written = hecal::io::FormatCameraYaml(c, {});
  const hecal::pose::CameraModel back = hecal::io::ParseCameraFile(written, "written").camera;
  if (back.fx != c.fx || back.fy != c.fy || back.cx != c.cx || back.cy != c.cy ||
      back.distortion != c.distortion || back.width != c.width || back.height != c.height) {
    std::abort();
  }
  return 0;
}
