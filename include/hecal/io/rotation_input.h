// Rotations read from files: how far a written rotation matrix or quaternion may be from an exact
// rotation, what hecal does with it, and what it says when it refuses. One rule for every reader:
// the pose tables (pose_table.h: r11..r33, qw..qz and q1..q4 columns, 12/16-number lines) and every
// `hecal import` format (import.h). Documented for users in docs/pose-files.md and
// docs/import-formats.md.
//
// Matrices. e = so3::OrthonormalityError(M) = max(|MᵀM − I|, |det M − 1|) (entries), and u = the
// largest rounding of the nine printed entries (PrintedRounding; 0 where the text is not known,
// e.g. JSON numbers).
//   e ≤ 1e-6               projected onto SO(3) (NearestRotationSvd: the nearest rotation in the
//                          Frobenius norm), silently;
//   1e-6 < e ≤ tolerance   projected, and the source gets one note (Notes());
//   e > tolerance          refused (hecal::InputError) with the reason, from det M and the
//                          singular values σ1 ≥ σ2 ≥ σ3 of M, tried in this order:
//     det M < 0                  "a reflection (det R = -1)": a handedness or axis-sign mistake;
//     NearestRotationSvd(M) is   the printed digits alone can explain e, so they are too coarse
//       within u of every entry, to hold a rotation: "write more digits" (the only case that says
//       u ≤ 0.05                 so; a sufficient test, never a guess);
//     M/s within the tolerance   "a rotation scaled by 1.5", s = (det M)^(1/3): a scale (a unit
//       and 10× closer to SO(3)  conversion) applied to the rotation part;
//       than M
//     otherwise                  not orthonormal (a shear, a wrong or misplaced entry): the
//                                message gives e and the singular values.
//   tolerance = min(max(1e-3, 6u), 1e-2).
// Why these numbers (e of real files, and what the limits still catch):
//   - 6-decimal files: Tabb & Ahmad Yousef's robot_cali.txt (data/tabb-rwhe-dataset1) has e up to
//     1.3e-6. Rounding each entry of a rotation by at most u changes MᵀM by at most 2√3·u + 3u²
//     and det M by at most 3√3·u + O(u²), so e ≤ 6u: 3e-6 at 6 decimals, 3e-3 at 3 decimals.
//   - Robot controllers report matrices that are not exactly orthonormal even when printed with
//     17 digits (libfranka's O_T_EE: e = 1.9e-5; controllers generally 1e-5 to 1e-4), and
//     libfranka itself refuses a 3-decimal "0.707" end-effector rotation that "0.7071" fixes
//     (github.com/frankarobotics/libfranka/issues/16); OpenCV's calibrateHandEye and ViSP take
//     such matrices (ViSP added vpRotationMatrix::orthogonalize() for pasted low-precision
//     rotations, github.com/lagadic/visp/pull/1038).
//   - 1e-3 (6u for coarser prints) accepts all of these while every real mistake is far beyond
//     it: a reflection or a swapped pair of axes has e = 2, a scale of 1.5 has e = 2.4, a
//     misplaced entry or a translation in the 3×3 block has e ≫ 0.01. The projection keeps R of
//     the polar decomposition M = R·P and drops only P = (MᵀM)^½, the part that is not a rotation
//     (entries move by the order of e; 1e-3 rad = 0.06°). The cap 1e-2 keeps 1- and 2-decimal
//     prints from passing as rotations.
//
// Quaternions (w, x, y, z). n = ‖q‖, computed without overflow or underflow.
//   n ≤ 1e-12              refused: a zero quaternion;
//   |n − 1| ≤ 1e-6         normalised silently;
//   |n − 1| ≤ tolerance    normalised, with a note; tolerance = min(max(1e-3, 3u), 1e-2), as 4
//                          entries rounded by u change the norm by at most 2u;
//   otherwise              refused: "quaternion norm 1.73, not 1: not a unit quaternion" with a fix
//                          asking whether the four values are the quaternion the layout names
//                          (unit quaternions in permuted order still have norm 1; a norm far from
//                          1 means other numbers — a shifted column, Euler angles — were read), or
//                          "write more digits" when q/n is within u of every entry (u ≤ 0.05).
//
// Notes: one line per source and kind (matrices, quaternions), not per row, e.g.
//   "robot.csv: 88 of 88 rotation matrices were not orthonormal within 1e-6 (largest error
//    1.9e-05 at line 12); projected onto the nearest rotation (largest change of an entry 1.1e-05)"
// Readers put them in PoseTable::warnings; the CLI prints them and `hecal import` also writes them
// as '#' lines in its output files.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace hecal::io {

// The rounding bound of a printed decimal number: 0.5·10^(exponent − fraction digits), e.g.
// "0.985976" → 5e-7, "1.5E+2" → 5, "1.17359e-06" → 5e-12; 0 for numbers without fraction digits
// ("1", "1.", "1e-5"), which are taken as exact.
double PrintedRounding(std::string_view number);

// Where a rotation sits in its source, for messages and notes.
struct RotationPlace {
  int line = 0;      // 1-based line; 0 when unknown (e.g. JSON)
  std::string what;  // e.g. "T1_3", "sample 4 M_eef"; empty for table rows (the line says it)
};

// Applies the rule above to the rotations of one source (a file, or one table of a file) and
// collects what its notes need.
class RotationInput {
 public:
  // `source` names the file in errors and notes; `subject` ("robot", "camera", or empty) says
  // whose rotations they are when one file holds both.
  explicit RotationInput(std::string source, std::string subject = "");

  // The rotation nearest to M (finite entries, row-major as written). `rounding` is the largest
  // PrintedRounding of its nine entries. Throws InputError(source, place.line, ...) when M is
  // refused.
  Eigen::Matrix3d Matrix(const Eigen::Matrix3d& M, double rounding, const RotationPlace& place);

  // The rotation of the Hamilton quaternion wxyz (finite entries), normalised. `rounding` as for
  // Matrix; `columns` names the four values in the source's layout (e.g. "qw,qx,qy,qz", "rotation
  // {x, y, z, w}") for the refusal's fix. Throws InputError when refused.
  Eigen::Matrix3d Quaternion(const Eigen::Vector4d& wxyz, double rounding,
                             const RotationPlace& place, std::string_view columns);

  // One line per kind of rotation that needed more than rounding-level correction (empty when
  // every rotation was within 1e-6).
  std::vector<std::string> Notes() const;

 private:
  struct Largest {
    int count = 0;     // rotations beyond 1e-6
    int total = 0;     // rotations read
    double error = 0;  // the largest e or |n − 1|
    double rounding = 0;
    RotationPlace place;
    double change = 0;  // matrices: the largest change of an entry by the projection
  };
  std::string source_;
  std::string subject_;
  Largest matrices_;
  Largest quaternions_;
};

}  // namespace hecal::io
