// libFuzzer target for the YAML importers: camodocal (OpenCV FileStorage), easy_handeye and
// opencv-yaml. The first byte picks the reader (byte % 3) and its options (byte / 3: easy_handeye
// --setup, opencv-yaml --units); the rest is the file. Any exception other than hecal::InputError,
// any crash, and any accepted input that breaks testing/import_properties.h is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "testing/import_properties.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hecal::testing::RunImportFuzzInput(hecal::testing::ImportFuzzer::kYaml,
                                     std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
