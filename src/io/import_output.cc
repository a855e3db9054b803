// The files an import writes: see import_output.h.
#include "hecal/io/import_output.h"

#include <vector>

#include "hecal/io/pose_table.h"

namespace hecal::io {
namespace {

std::string PoseCsv(const PoseTable& table, const std::vector<std::string>& notes,
                    const std::string& provenance) {
  PoseWriteOptions write;  // quaternion rotation (the default RotationFormat)
  write.units = table.unit;
  write.comments.push_back(provenance);
  write.comments.insert(write.comments.end(), notes.begin(), notes.end());
  for (const std::string& warning : table.warnings) write.comments.push_back("note: " + warning);
  return FormatPoseTable(table, write);
}

}  // namespace

ImportTexts FormatImportedPoses(const ImportedPoses& imported, const std::string& provenance) {
  ImportTexts texts;
  texts.robot = PoseCsv(imported.robot, imported.robot_notes, provenance);
  if (imported.camera) texts.camera = PoseCsv(*imported.camera, imported.camera_notes, provenance);
  if (imported.intrinsics) {
    texts.intrinsics = FormatIntrinsicsYaml(
        *imported.intrinsics,
        {provenance,
         "source: " + imported.intrinsics->source +
             " (K and plumb_bob distortion k1 k2 p1 p2 k3, pixels)",
         "width and height are not in the source; add them if a tool needs them"});
  }
  return texts;
}

}  // namespace hecal::io
