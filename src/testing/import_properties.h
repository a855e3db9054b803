// Properties every successful import must have, checked by the import fuzzers
// (fuzz/fuzz_import_*.cc) and by the replay of their findings
// (src/io/import_fuzz_corpus_test.cc, tests/data/fuzz-regressions/import_*/). A violation
// aborts, so libFuzzer reports it as a crash.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "hecal/io/import_camodocal.h"
#include "hecal/io/import_easy_handeye.h"
#include "hecal/io/import_ethz.h"
#include "hecal/io/import_matrix16.h"
#include "hecal/io/import_moveit.h"
#include "hecal/io/import_opencv_yaml.h"
#include "hecal/io/import_tabb.h"
#include "hecal/io/pose_table.h"

namespace hecal::testing {

inline void ImportPropertyFailed(const char* what) {
  std::fprintf(stderr, "import property violated: %s\n", what);
  std::abort();
}

inline void CheckTable(const io::PoseTable& table) {
  if (table.rows.empty()) ImportPropertyFailed("an empty table was returned");
  for (const io::PoseRow& row : table.rows) {
    if (!row.pose.matrix().allFinite()) ImportPropertyFailed("a pose is not finite");
    if (so3::OrthonormalityError(row.pose.linear()) > 1e-9) {
      ImportPropertyFailed("a rotation is not orthonormal");
    }
    if (!row.id || row.id->empty()) ImportPropertyFailed("a row has no id");
  }
  // The written table must format (ids without line breaks, finite stamps and positions).
  io::PoseWriteOptions options;
  options.units = table.unit;
  try {
    io::FormatPoseTable(table, options);
  } catch (const InputError&) {
    ImportPropertyFailed("an imported table cannot be written");
  }
}

inline void CheckImported(const io::ImportedPoses& poses) {
  CheckTable(poses.robot);
  if (poses.camera) {
    CheckTable(*poses.camera);
    if (poses.synchronised && poses.camera->rows.size() != poses.robot.rows.size()) {
      ImportPropertyFailed("paired robot and camera tables differ in length");
    }
  }
}

// Runs one importer on fuzz input. `selector` picks the reader and its options; `text` is the
// file (for two-file formats it is split at the first '\x1e' byte: robot, then camera).
enum class ImportReader { kCamodocal, kEasyHandeye, kOpenCvYaml, kMoveit, kTabb, kEthz, kMatrix16 };

inline void RunImportProperty(ImportReader reader, unsigned char options, std::string_view text) {
  const size_t split = text.find('\x1e');
  const std::string_view first = text.substr(0, split);
  const std::string_view second =
      split == std::string_view::npos ? std::string_view() : text.substr(split + 1);
  try {
    switch (reader) {
      case ImportReader::kCamodocal:
        CheckImported(io::ParseCamodocalPairs(text, "fuzz.yml"));
        break;
      case ImportReader::kEasyHandeye: {
        std::optional<io::ImportSetup> setup;
        if (options % 3 == 1) setup = io::ImportSetup::kEyeInHand;
        if (options % 3 == 2) setup = io::ImportSetup::kEyeToHand;
        CheckImported(io::ParseEasyHandeyeSamples(text, "fuzz.yaml", setup));
        break;
      }
      case ImportReader::kOpenCvYaml:
        CheckImported(io::ParseOpenCvHandEyeYaml(
            text, "fuzz.yml", options % 2 ? io::LengthUnit::kMillimetre : io::LengthUnit::kMetre));
        break;
      case ImportReader::kMoveit:
        CheckImported(io::ParseMoveitSamples(text, "fuzz.json"));
        break;
      case ImportReader::kTabb:
        CheckImported(io::ParseTabb(first, "robot_cali.txt", second, "cali.txt"));
        break;
      case ImportReader::kEthz:
        CheckImported(io::ParseEthzStreams(first, "robot.csv", second, "camera.csv"));
        break;
      case ImportReader::kMatrix16: {
        io::Matrix16Options matrix;
        matrix.unit = options % 2 ? io::LengthUnit::kMillimetre : io::LengthUnit::kMetre;
        if (split == std::string_view::npos) {
          CheckImported(io::ParseMatrix16(first, "robot.txt", std::nullopt, "", matrix));
        } else {
          CheckImported(io::ParseMatrix16(first, "robot.txt", second, "camera.txt", matrix));
        }
        break;
      }
    }
  } catch (const InputError&) {
    // Rejected with a message: the expected outcome for most fuzz inputs.
  }
}

// The byte layout of each import fuzzer (fuzz/fuzz_import_*.cc), shared with the replay of their
// findings so a kept input means the same thing to both.
enum class ImportFuzzer { kText, kYaml, kJson };

inline void RunImportFuzzInput(ImportFuzzer fuzzer, std::string_view bytes) {
  if (fuzzer == ImportFuzzer::kJson) {
    RunImportProperty(ImportReader::kMoveit, 0, bytes);
    return;
  }
  if (bytes.empty()) return;
  constexpr ImportReader kText[] = {ImportReader::kTabb, ImportReader::kEthz,
                                    ImportReader::kMatrix16};
  constexpr ImportReader kYaml[] = {ImportReader::kCamodocal, ImportReader::kEasyHandeye,
                                    ImportReader::kOpenCvYaml};
  const auto selector = static_cast<unsigned char>(bytes[0]);
  const ImportReader reader =
      fuzzer == ImportFuzzer::kText ? kText[selector % 3] : kYaml[selector % 3];
  RunImportProperty(reader, static_cast<unsigned char>(selector / 3), bytes.substr(1));
}

}  // namespace hecal::testing
