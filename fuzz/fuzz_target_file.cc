// libFuzzer target for the target.yaml reader (io/target_file.h). Any exception other than
// hecal::InputError and any crash is a finding; an accepted target must pass pose::CheckTarget
// (the reader's own contract) and give object points with finite coordinates.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/io/target_file.h"
#include "hecal/pose/target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const hecal::pose::TargetSpec target = hecal::io::ParseTargetYaml(text, "target.yaml");
    for (const hecal::pose::ObjectPoint& point : hecal::pose::ObjectPoints(target)) {
      if (!point.position.allFinite()) std::abort();
    }
  } catch (const hecal::InputError&) {
  }
  return 0;
}
