// The convention check of `hecal calibrate` (both forms): before solving, the data as given are
// compared with the mistakes users make (handeye/convention_diagnosis.h: the other setup, an
// inverted file, millimetres read as metres, quaternion columns one place off). When one fits
// clearly better the command stops with exit 2 and says which, with both residuals and the flag
// that fixes it — it never switches silently. `--setup auto` picks the setup that fits and
// reports the evidence; when neither fits clearly better it asks for --setup.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/handeye/convention_diagnosis.h"
#include "hecal/handeye/problem.h"
#include "hecal/handeye/station_consensus.h"
#include "hecal/io/pose_table.h"

namespace hecal::cli {

// What the user gave, for the fix texts.
struct ConventionFlags {
  std::string robot_file;
  std::string camera_file;     // empty: camera poses from --images
  bool robot_inverse = false;  // --robot-inverse was given
  bool camera_inverse = false;
  bool robot_matrix_lines =
      false;  // the robot file is 12/16-number lines (no header to name a unit)
  bool camera_matrix_lines = false;
};

struct ConventionCheck {
  handeye::Setup setup = handeye::Setup::kEyeInHand;  // given, or chosen by --setup auto
  std::vector<std::string> notes;  // the evidence for --setup auto, for the printout and result
};

// `data.setup` is ignored when `setup` is nullopt (--setup auto). Throws InputError naming the
// mistake when an alternative fits clearly better than the data as given (or, with auto, than
// the setup that fits best), and when auto cannot tell the setups apart.
ConventionCheck CheckConventions(handeye::PoseData data, std::optional<handeye::Setup> setup,
                                 const ConventionFlags& flags,
                                 const handeye::ConsensusOptions& options);

// The table's rotations were quaternion columns (their order can be mislabelled).
bool HasQuaternionColumns(const io::PoseTable& table);

// "0.78 deg / 1.3 mm" (lengths ≥ 1 m in m).
std::string ResidualText(double rotation_rad, double translation_m);

}  // namespace hecal::cli
