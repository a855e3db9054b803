// The files an import writes (docs/import-formats.md, the output table): the imported robot and
// camera tables as pose CSVs (pose_table.h: quaternions qw,qx,qy,qz, an id column, a stamp column
// when the source has stamps, lengths in the source's unit) and the source's intrinsics as
// camera.yaml (import_types.h's FormatIntrinsicsYaml: fx, fy, cx, cy, plumb_bob distortion,
// pixels).
//
// '#' lines of a pose CSV, in order: the caller's `provenance` (which program wrote it, from
// which format), the reader's notes (the source, the convention applied, the units), then
// "note: W" for each of the table's warnings (rotations projected onto SO(3) or normalised,
// rotation_input.h). Of camera.yaml: `provenance`, the source file and the model, and that width
// and height are not in the source.
// Errors: those of FormatPoseTable (InputError).
#pragma once

#include <optional>
#include <string>

#include "hecal/io/import_types.h"

namespace hecal::io {

struct ImportTexts {
  std::string robot;                      // robot.csv: T_base_gripper
  std::optional<std::string> camera;      // camera.csv: T_camera_target, when imported
  std::optional<std::string> intrinsics;  // camera.yaml, when the source has one camera model
};

ImportTexts FormatImportedPoses(const ImportedPoses& imported, const std::string& provenance);

}  // namespace hecal::io
