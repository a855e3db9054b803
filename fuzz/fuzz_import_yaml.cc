// libFuzzer target for the YAML importers: camodocal (OpenCV FileStorage), easy_handeye and
// opencv-yaml. The first byte picks the reader (byte % 3) and its options (byte / 3: easy_handeye
// --setup, opencv-yaml --units); the rest is the file. Any exception other than hecal::InputError,
// any crash, and any accepted input that breaks testing/import_properties.h is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "testing/import_properties.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  using hecal::testing::ImportReader;
  constexpr ImportReader kReaders[] = {ImportReader::kCamodocal, ImportReader::kEasyHandeye,
                                       ImportReader::kOpenCvYaml};
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  hecal::testing::RunImportProperty(kReaders[data[0] % 3], static_cast<unsigned char>(data[0] / 3),
                                    text);
  return 0;
}
