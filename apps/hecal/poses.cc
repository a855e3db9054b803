// `hecal poses convert`: see poses.h and docs/pose-files.md.
#include "poses.h"

#include <CLI/CLI.hpp>
#include <memory>

#include "choice_flags.h"
#include "hecal/hecal.h"

namespace hecal::cli {
namespace {

constexpr const char* kConvertFooter =
    R"(Input: CSV with a header naming x,y,z and one rotation group
  (qw,qx,qy,qz | rx,ry,rz | r11..r33 | a1,a2,a3 with --euler SEQ | roll,pitch,yaw | a,b,c |
  w,p,r | q1..q4), optional id and stamp; or 12/16 numbers per line (row-major 3x4/4x4).
Units: header suffixes (x_mm, a_deg, rx_rad) win over flags. Without suffixes the input is in
  --input-units (default m) and radians (--input-degrees for degrees; kuka a,b,c and fanuc
  w,p,r default to degrees).
  --units and --degrees apply to the OUTPUT: length defaults to the input's unit, angles to
  radians (kuka and fanuc are always written in degrees). Units other than m/rad are named in the
  output header (x_mm, a_deg), so the file reads back the same without flags.
  euler:SEQ output starts with a '# euler: SEQ' line that declares the sequence of a1,a2,a3.
Output: id and stamp columns are kept; quaternions have qw >= 0; --invert writes T^-1.
Errors: one line on stderr, exit code 2, and no output file.)";

}  // namespace

void RunPosesConvert(const jobs::PoseConversionOptions& options, const std::string& output,
                     const Io& io) {
  io::CheckOutputs({{"--output", output}}, {{"--input", options.input}});
  const jobs::PoseConversion result = jobs::ConvertPoseTable(options);
  for (const std::string& warning : result.table.warnings) {
    io.err << "hecal: warning: " << warning << "\n";
  }
  io::WritePoseTable(output, result.table, result.write);

  const io::RotationFormat& format = options.to;
  const bool angles = format.kind == io::RotationFormat::Kind::kRotationVector ||
                      format.kind == io::RotationFormat::Kind::kEuler;
  io.out << "hecal: wrote " << result.table.rows.size() << " poses to " << output << " ("
         << format.ToString() << ", " << io::UnitName(result.write.units)
         << (angles ? (options.degrees || format.angles_in_degrees ? ", degrees" : ", radians")
                    : "")
         << (options.read.invert ? ", inverted" : "") << ")\n";
}

void RegisterPosesCommand(CLI::App& app, const Io& io) {
  CLI::App* poses = app.add_subcommand("poses", "Pose files: convert rotation forms and units");
  poses->require_subcommand(1);

  auto options = std::make_shared<jobs::PoseConversionOptions>();
  auto output = std::make_shared<std::string>();
  CLI::App* convert =
      poses->add_subcommand("convert", "Convert a pose table to another rotation form and/or unit");
  convert->add_option("--input", options->input, "Input pose table (CSV or matrix lines)")
      ->required();
  convert->add_option("--output", *output, "Output CSV (written atomically)")->required();
  AddChoice<io::RotationFormat>(
      *convert, "--to", options->to, io::ParseRotationFormat, "rotation format",
      "one of " + std::string(io::RotationFormatSpellings()),
      "Rotation form: quaternion | rotvec | matrix | euler:SEQ (e.g. euler:ZYX, euler:xyz; "
      "lowercase = extrinsic, uppercase = intrinsic) | rpy | kuka | fanuc | abb | ur")
      ->required();
  AddLengthUnitFlag(*convert, "--units", options->units,
                    "Output length unit m|mm (default: the input's unit)");
  convert->add_flag("--degrees", options->degrees,
                    "Output angles in degrees (rotvec, euler:SEQ, rpy; kuka/fanuc always are)");
  convert->add_flag("--invert", options->read.invert, "Write the inverse of every pose");
  AddLengthUnitFlag(*convert, "--input-units", options->read.units,
                    "Input length unit m|mm when the header has no suffix (default m)");
  convert->add_flag("--input-degrees", options->read.degrees,
                    "Input angles in degrees when the header has no suffix");
  AddEulerFlag(*convert, "--euler", options->read.euler,
               "Euler sequence of a1,a2,a3 input columns (e.g. ZYX, xyz)");
  convert->footer(kConvertFooter);
  convert->callback([options, output, io] { RunPosesConvert(*options, *output, io); });
}

}  // namespace hecal::cli
