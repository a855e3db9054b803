// libFuzzer target for the plain-text importers: tabb (robot_cali.txt + cali.txt), ethz (two pose
// CSVs) and matrix16. The first byte picks the reader (byte % 3) and its options (byte / 3:
// matrix16 units); the rest is the file, or two files separated by a 0x1e byte.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "testing/import_properties.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hecal::testing::RunImportFuzzInput(hecal::testing::ImportFuzzer::kText,
                                     std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
