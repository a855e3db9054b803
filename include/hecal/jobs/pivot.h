// Tool-centre-point calibration by pivoting as one job (`hecal pivot`, docs/pivot.md; `hecal.pivot`
// would be its Python door): the robot poses in, report::PivotDocument out, printing nothing.
//
// CalibratePivotPoses (poses in memory)
//   1. The options checked (IsValid); every pose finite with a proper rotation (CheckPoseList of
//      pose_calibration.h); translations converted from options.unit to metres.
//   2. estimation::CalibratePivot (estimation/pivot.h): the algebraic start, the geometric fit,
//      the noise, the covariance, the outlier flags and the degeneracy checks.
// CalibratePivotFile (a pose table)
//   1. The options checked before the file is read.
//   2. The table read (io/pose_table.h: units, angles, Euler sequence, invert on reading); its
//      warnings follow the estimator's in the document.
//   3. estimation::CalibratePivot; the stations named by the table's id column, or the 0-based
//      row index as text (as io::PairStations names them).
// Frames and units: T_base_flange maps flange coordinates to base coordinates; the tip t_tip in
// the flange frame, the pivot p in the base frame; metres inside, the document labelled in the
// table's (or options.unit's) length unit.
//
// Errors: InputError for invalid options (source the field: PivotOptions.sigma,
// PivotPoseOptions.source, PivotFileOptions.robot, PoseReadOptions.units), a pose that is not
// finite or not a rotation, and those of the table (file, line, what, fix); DegenerateError from
// the estimator (too few stations, too little rotation, rotation about one axis only). Nothing is
// written.
#pragma once

#include <string>
#include <vector>

#include "hecal/estimation/pivot.h"
#include "hecal/io/pose_table.h"
#include "hecal/io/units.h"
#include "hecal/report/pivot_file.h"

namespace hecal::jobs {

struct PivotPoseOptions {
  estimation::PivotOptions pivot;                // noise (nullopt: estimated), outlier rejection
  io::LengthUnit unit = io::LengthUnit::kMetre;  // the unit of the poses' translations
  std::vector<std::string> station_ids;          // one per pose; empty: "0", "1", ...
  std::string source = "T_base_flange";          // the list's name in errors

  // core/options_check.h: PivotOptions::IsValid, then PivotPoseOptions.source (empty).
  bool IsValid(std::string* why) const;
};

// Steps 1–2 of CalibratePivotPoses above.
report::PivotDocument CalibratePivotPoses(const std::vector<Pose>& T_base_flange,
                                          const PivotPoseOptions& options);

struct PivotFileOptions {
  std::string robot;         // the pose table T_base_flange, one row per station
  io::PoseReadOptions read;  // its units, angles, Euler sequence; invert on reading
  estimation::PivotOptions pivot;

  // core/options_check.h: PivotOptions::IsValid, PivotFileOptions.robot (empty), then
  // PoseReadOptions::IsValid.
  bool IsValid(std::string* why) const;
};

// Steps 1–3 of CalibratePivotFile above.
report::PivotDocument CalibratePivotFile(const PivotFileOptions& options);

}  // namespace hecal::jobs
