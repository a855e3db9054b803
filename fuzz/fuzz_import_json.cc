// libFuzzer target for the JSON importer (MoveIt Calibration pose_samples.json). The whole input
// is the file. Any exception other than hecal::InputError, any crash, and any accepted input that
// breaks testing/import_properties.h is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "testing/import_properties.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hecal::testing::RunImportFuzzInput(hecal::testing::ImportFuzzer::kJson,
                                     std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
