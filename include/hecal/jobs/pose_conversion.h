// The pose-table conversion job (`hecal poses convert`, docs/pose-files.md): reads a pose table
// (any rotation group, units from header suffixes or the read options, or 12/16-number matrix
// lines), optionally inverted (io::PoseReadOptions::invert), and returns it with the write options
// that give it the requested rotation form and units. It writes nothing: the caller writes
// FormatPoseTable(result.table, result.write), or WritePoseTable (atomic).
//
// Units of the result: `units` when given, else the input's length unit; angles in degrees when
// `degrees` (kuka and fanuc are always written in degrees). The written header names any unit
// that is not metres/radians (x_mm, a_deg), so the file reads back the same without options.
//
// Errors: hecal::InputError from io::ReadPoseTable (source: the input path, with the line), and
// when !options.IsValid (PoseConversionOptions.input empty).
#pragma once

#include <optional>
#include <string>

#include "hecal/io/pose_table.h"
#include "hecal/io/rotation_format.h"
#include "hecal/io/units.h"

namespace hecal::jobs {

struct PoseConversionOptions {
  std::string input;                    // the pose table to read
  io::PoseReadOptions read;             // input units, degrees, Euler sequence, invert
  io::RotationFormat to;                // the rotation form written
  std::optional<io::LengthUnit> units;  // nullopt: the input's unit
  bool degrees = false;                 // write angles in degrees

  // core/options_check.h: false naming PoseConversionOptions.input when empty.
  bool IsValid(std::string* why) const;
};

struct PoseConversion {
  io::PoseTable table;         // as read (inverted when read.invert), its warnings included
  io::PoseWriteOptions write;  // rotation, units, degrees of the output
};

PoseConversion ConvertPoseTable(const PoseConversionOptions& options);

}  // namespace hecal::jobs
