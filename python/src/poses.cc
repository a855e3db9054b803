// Pose tables (docs/python.md#pose-files): hecal.read_poses and hecal.write_poses, the files of
// docs/pose-files.md through io::ReadPoseTable / io::WritePoseTable — every rotation form the
// CLI reads and writes (quaternion, rotvec, matrix, euler:SEQ, and the presets rpy, kuka, fanuc,
// abb, ur), 12/16-number matrix lines, units and angle units. Arrays are N×4×4 T_a_b in metres
// (hecal's unit in memory; a file's unit is converted on reading and writing).
#include <string>

#include "bindings.h"

namespace hecal::python {
namespace {

io::LengthUnit UnitArgument(const std::string& argument, const std::string& text) {
  const auto unit = io::ParseLengthUnit(text);
  if (!unit) ThrowArgument(argument, "unknown length unit '" + text + "'", "use 'm' or 'mm'");
  return *unit;
}

constexpr const char* kReadDoc = R"doc(read_poses(path, units="m", degrees=False, euler=None, invert=False) -> (poses, ids)

Read a pose table (docs/pose-files.md): CSV with a header naming x,y,z and one rotation group
(qw,qx,qy,qz | rx,ry,rz | r11..r33 | a1,a2,a3 | roll,pitch,yaw | a,b,c | w,p,r | q1..q4),
optional id and stamp columns; or 12/16 numbers per line (row-major 3x4 / 4x4).

units    length unit of columns without a suffix (x_mm, x_m win): "m" (default) or "mm"
degrees  angles without a suffix are in degrees (kuka a,b,c and fanuc w,p,r default to degrees)
euler    Euler sequence of a1,a2,a3 columns, e.g. "ZYX" (intrinsic) or "xyz" (extrinsic)
invert   return the inverse of every pose

Returns poses, an (N, 4, 4) float64 array of the file's transforms in METRES, and ids, one
str per row (the id column, or the 0-based row index). Rotations within the reader's
tolerance of orthonormal are projected (warnings are not returned; the CLI prints them).
Raises hecal.InputError naming the file and line (missing file, bad number, unknown column...).)doc";

constexpr const char* kWriteDoc = R"doc(write_poses(path, poses, to="quaternion", units="m", degrees=False, ids=None, stamps=None, comments=None)

Write an (N, 4, 4) array of poses (METRES) as a pose table (docs/pose-files.md), atomically.

to       rotation form: "quaternion" | "rotvec" | "matrix" | "euler:SEQ" (e.g. "euler:ZYX"
         intrinsic, "euler:xyz" extrinsic) | "rpy" | "kuka" | "fanuc" | "abb" | "ur"
units    output length unit "m" or "mm" (named in the header, x_mm)
degrees  angles in degrees (rotvec, euler, rpy; kuka and fanuc always are)
ids      one id per pose (written as the id column); stamps: one time per pose (seconds)
comments '#' lines written before the header
The file reads back to the same poses with read_poses and default options.)doc";

}  // namespace

void RegisterPoses(py::module_& m) {
  m.def(
      "read_poses",
      [](py::handle path, const std::string& units, bool degrees,
         std::optional<std::string> euler, bool invert) {
        const auto file = AsPath(path);
        if (!file) ThrowArgument("path", "is not a path", "give a str or os.PathLike");
        io::PoseReadOptions options;
        options.units = UnitArgument("units", units);
        options.degrees = degrees;
        options.invert = invert;
        if (euler) {
          options.euler = EulerSequence::Parse(*euler);
          if (!options.euler) {
            ThrowArgument("euler", "unknown Euler sequence '" + *euler + "'",
                          "three letters of x, y, z: lowercase extrinsic ('xyz'), uppercase "
                          "intrinsic ('ZYX')");
          }
        }
        io::PoseTable table;
        {
          py::gil_scoped_release release;
          table = io::ReadPoseTable(*file, options);
        }
        std::vector<Pose> poses;
        std::vector<std::string> ids;
        for (size_t i = 0; i < table.rows.size(); ++i) {
          poses.push_back(table.rows[i].pose);
          ids.push_back(table.rows[i].id.value_or(std::to_string(i)));
        }
        return py::make_tuple(ArrayFromPoses(poses), ids);
      },
      py::arg("path"), py::kw_only(), py::arg("units") = "m", py::arg("degrees") = false,
      py::arg("euler") = py::none(), py::arg("invert") = false, kReadDoc);

  m.def(
      "write_poses",
      [](py::handle path, py::handle poses, const std::string& to, const std::string& units,
         bool degrees, std::optional<std::vector<std::string>> ids,
         std::optional<std::vector<double>> stamps, std::vector<std::string> comments) {
        const auto file = AsPath(path);
        if (!file) ThrowArgument("path", "is not a path", "give a str or os.PathLike");
        const std::vector<Pose> T = PosesFromArray(poses, "poses");
        if (ids && ids->size() != T.size()) {
          ThrowArgument("ids", "has " + std::to_string(ids->size()) + " ids for " +
                                   std::to_string(T.size()) + " poses",
                        "give one id per pose");
        }
        if (stamps && stamps->size() != T.size()) {
          ThrowArgument("stamps", "has " + std::to_string(stamps->size()) + " stamps for " +
                                      std::to_string(T.size()) + " poses",
                        "give one stamp per pose");
        }
        io::PoseWriteOptions options;
        const auto format = io::ParseRotationFormat(to);
        if (!format) {
          ThrowArgument("to", "unknown rotation form '" + to + "'",
                        "use one of " + std::string(io::RotationFormatSpellings()));
        }
        options.rotation = *format;
        options.units = UnitArgument("units", units);
        options.degrees = degrees;
        options.comments = std::move(comments);
        io::PoseTable table;
        table.source = *file;
        for (size_t i = 0; i < T.size(); ++i) {
          io::PoseRow row;
          row.pose = T[i];
          if (ids) row.id = (*ids)[i];
          if (stamps) row.stamp = (*stamps)[i];
          table.rows.push_back(std::move(row));
        }
        py::gil_scoped_release release;
        io::WritePoseTable(*file, table, options);
      },
      py::arg("path"), py::arg("poses"), py::kw_only(), py::arg("to") = "quaternion",
      py::arg("units") = "m", py::arg("degrees") = false, py::arg("ids") = py::none(),
      py::arg("stamps") = py::none(), py::arg("comments") = std::vector<std::string>(), kWriteDoc);
}

}  // namespace hecal::python
