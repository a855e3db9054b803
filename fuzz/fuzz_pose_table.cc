// libFuzzer target for the pose-table reader (docs/pose-files.md) and, through the round trip, the
// writer. The first byte picks the reader options (units, degrees, invert, Euler sequence; see
// PoseReadOptionsFromByte), the rest is the file. Properties: testing/pose_table_properties.h.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "testing/pose_table_properties.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  hecal::testing::CheckPoseTableProperties(text, hecal::testing::PoseReadOptionsFromByte(data[0]));
  return 0;
}
