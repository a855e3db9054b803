// The rotation-reading rule of rotation_input.h: limits, projection, refusal reasons and notes.
#include "hecal/io/rotation_input.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "hecal/core/error.h"
#include "hecal/geometry/nearest_rotation.h"
#include "hecal/geometry/rotation.h"
#include "hecal/geometry/so3.h"
#include "import_internal.h"

namespace hecal::io {
namespace {

using import_internal::Scientific;

constexpr double kSilent = 1e-6;           // below: rounding noise, corrected without a note
constexpr double kTolerance = 1e-3;        // accepted with a note up to here ...
constexpr double kWidestTolerance = 1e-2;  // ... or up to the printed-digits bound, capped here
constexpr double kCoarsestDigits = 0.05;   // "more digits" is advice only from 1 decimal on
constexpr double kScaleExplains = 0.1;     // M/s at least 10 times closer to SO(3) than M
constexpr double kZeroNorm = 1e-12;

double Tolerance(double bound) {
  return std::min(std::max(kTolerance, bound), kWidestTolerance);
}

// "%.6g": a value the user recognises (a norm, a scale, a determinant, a singular value).
std::string Short(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return buffer;
}

std::string Prefix(const RotationPlace& place) {
  return place.what.empty() ? std::string() : place.what + ": ";
}

std::string Allowed(double tolerance, double rounding, double bound) {
  std::string text = "more than the " + Scientific(tolerance) + " allowed";
  if (bound > kTolerance) text += " for entries printed to +-" + Scientific(rounding);
  return text;
}

std::string Where(const RotationPlace& place) {
  if (place.line > 0 && !place.what.empty()) {
    return "line " + std::to_string(place.line) + " (" + place.what + ")";
  }
  if (place.line > 0) return "line " + std::to_string(place.line);
  return place.what;
}

struct Shape {
  Eigen::Vector3d singular_values = Eigen::Vector3d::Zero();  // descending
  double determinant = 0.0;
};

// Singular values and determinant of M, computed on M / max|M_ij| so that neither overflows.
Shape ShapeOf(const Eigen::Matrix3d& M) {
  Shape shape;
  const double largest = M.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) return shape;
  const Eigen::Matrix3d N = M / largest;
  // σ² are the eigenvalues of NᵀN (ascending).
  const Eigen::Vector3d squares =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(N.transpose() * N, Eigen::EigenvaluesOnly)
          .eigenvalues();
  for (int k = 0; k < 3; ++k) {
    shape.singular_values[k] = largest * std::sqrt(std::max(squares[2 - k], 0.0));
  }
  shape.determinant = N.determinant() * largest * largest * largest;
  return shape;
}

std::string SingularValues(const Shape& shape) {
  return "singular values " + Short(shape.singular_values[0]) + ", " +
         Short(shape.singular_values[1]) + ", " + Short(shape.singular_values[2]);
}

}  // namespace

double PrintedRounding(std::string_view number) {
  const size_t e = number.find_first_of("eE");
  const std::string_view mantissa = number.substr(0, e);
  const size_t dot = mantissa.find('.');
  if (dot == std::string_view::npos) return 0.0;
  int fraction_digits = 0;
  for (size_t i = dot + 1; i < mantissa.size() && mantissa[i] >= '0' && mantissa[i] <= '9'; ++i) {
    ++fraction_digits;
  }
  if (fraction_digits == 0) return 0.0;
  int exponent = 0;
  if (e != std::string_view::npos) {
    std::string_view text = number.substr(e + 1);
    bool negative = false;
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) {
      negative = text.front() == '-';
      text.remove_prefix(1);
    }
    for (const char c : text) {
      if (c < '0' || c > '9') break;
      exponent = std::min(exponent * 10 + (c - '0'), 1000);
    }
    if (negative) exponent = -exponent;
  }
  // Exact powers of ten for the usual prints, pow beyond them.
  static constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const int power = exponent - fraction_digits;
  if (power >= -22 && power <= 22) {
    return power >= 0 ? 0.5 * kPowers[power] : 0.5 / kPowers[-power];
  }
  return 0.5 * std::pow(10.0, power);
}

RotationInput::RotationInput(std::string source, std::string subject)
    : source_(std::move(source)), subject_(std::move(subject)) {}

Eigen::Matrix3d RotationInput::Matrix(const Eigen::Matrix3d& M, double rounding,
                                      const RotationPlace& place) {
  const double error = so3::OrthonormalityError(M);
  const double bound = 6.0 * rounding;
  const double tolerance = Tolerance(bound);
  ++matrices_.total;
  if (error <= tolerance) {
    const Eigen::Matrix3d R = NearestRotationSvd(M);
    if (error > kSilent) {
      ++matrices_.count;
      matrices_.change = std::max(matrices_.change, (R - M).cwiseAbs().maxCoeff());
      if (error > matrices_.error) {
        matrices_.error = error;
        matrices_.rounding = rounding;
        matrices_.place = place;
      }
    }
    return R;
  }

  const std::string prefix = Prefix(place);
  const std::string measure = "max(|R^T R - I|, |det R - 1|) = " + Scientific(error) + ", " +
                              Allowed(tolerance, rounding, bound);
  const Shape shape = ShapeOf(M);
  if (shape.determinant < 0.0) {
    const bool only_a_reflection = so3::OrthonormalityError(-M) <= tolerance;
    throw InputError(
        source_, place.line,
        prefix + "the rotation matrix is a reflection (det R = " + Short(shape.determinant) +
            "), not a rotation" +
            (only_a_reflection ? ""
                               : ", and not orthonormal either (" + SingularValues(shape) + ")"),
        "a handedness or axis-sign mistake: one axis (a row or column) has the wrong "
        "sign, or two axes are swapped; a rotation has det R = +1");
  }
  // The digits are the cause when a rotation (the nearest) lies within the rounding of every entry.
  if (rounding <= kCoarsestDigits &&
      (NearestRotationSvd(M) - M).cwiseAbs().maxCoeff() <= rounding) {
    throw InputError(
        source_, place.line,
        prefix + "the rotation matrix is printed too coarsely to be a rotation: " + measure,
        "write the rotation with more digits (at least 4 decimals; 17 significant "
        "digits keep a double exact)");
  }
  // A scale explains the error when M/s is within the tolerance and much closer to a rotation.
  const double scale = std::cbrt(shape.determinant);
  const double unscaled = scale > 0.0 ? so3::OrthonormalityError(M / scale) : error;
  if (unscaled <= tolerance && unscaled <= kScaleExplains * error) {
    throw InputError(source_, place.line,
                     prefix + "the rotation matrix is a rotation scaled by " + Short(scale) + " (" +
                         SingularValues(shape) + ")",
                     "divide the 3x3 block by " + Short(scale) +
                         ": a scale (e.g. a unit conversion) was applied to the rotation, which "
                         "has no unit; scale only the translation");
  }
  throw InputError(source_, place.line,
                   prefix + "the rotation matrix is not orthonormal: " + measure + " (" +
                       SingularValues(shape) + ")",
                   "check that the values are a rotation matrix written row-major (r11 r12 r13 "
                   "r21 ... r33) and that the columns are in the documented order");
}

Eigen::Matrix3d RotationInput::Quaternion(const Eigen::Vector4d& wxyz, double rounding,
                                          const RotationPlace& place, std::string_view columns) {
  // Scaled so that neither huge nor tiny components overflow or underflow the norm.
  const double largest = wxyz.cwiseAbs().maxCoeff();
  const Eigen::Vector4d unit_scale = largest > 0.0 ? Eigen::Vector4d(wxyz / largest) : wxyz;
  const double norm = largest > 0.0 ? largest * unit_scale.norm() : 0.0;
  const std::string prefix = Prefix(place);
  if (!(norm > kZeroNorm)) {
    throw InputError(
        source_, place.line,
        prefix + "zero quaternion (norm " + Scientific(norm) + ") cannot be a rotation",
        "write a unit quaternion (w=1,x=y=z=0 is no rotation)");
  }
  const double error = std::abs(norm - 1.0);
  const double bound = 3.0 * rounding;
  const double tolerance = Tolerance(bound);
  ++quaternions_.total;
  if (!(error <= tolerance)) {
    const std::string problem = prefix + "quaternion norm " + Short(norm) +
                                ", not 1 (|norm - 1| = " + Scientific(error) + ", " +
                                Allowed(tolerance, rounding, bound) + ")";
    // As for matrices: the nearest unit quaternion q/n is within the rounding of every entry.
    if (rounding <= kCoarsestDigits && (wxyz - wxyz / norm).cwiseAbs().maxCoeff() <= rounding) {
      throw InputError(source_, place.line, problem + ": printed too coarsely",
                       "write the quaternion with more digits (at least 4 decimals)");
    }
    throw InputError(source_, place.line, problem + ": not a unit quaternion",
                     "are " + std::string(columns) +
                         " a quaternion, in that order? A norm this far from 1 means other "
                         "numbers were read as the quaternion (a header naming the columns in a "
                         "different order than the values are written, or Euler angles)");
  }
  if (error > kSilent) {
    ++quaternions_.count;
    if (error > quaternions_.error) {
      quaternions_.error = error;
      quaternions_.rounding = rounding;
      quaternions_.place = place;
    }
  }
  return MatrixFromQuaternion(
      Eigen::Quaterniond(unit_scale[0], unit_scale[1], unit_scale[2], unit_scale[3]));
}

std::vector<std::string> RotationInput::Notes() const {
  std::vector<std::string> notes;
  const std::string whose = subject_.empty() ? std::string() : subject_ + " ";
  if (matrices_.count > 0) {
    std::string note = source_ + ": " + std::to_string(matrices_.count) + " of " +
                       std::to_string(matrices_.total) + " " + whose +
                       "rotation matrices were not orthonormal within 1e-6 (largest error " +
                       Scientific(matrices_.error) + " at " + Where(matrices_.place);
    if (matrices_.error <= 6.0 * matrices_.rounding) {
      note += ", within what entries printed to +-" + Scientific(matrices_.rounding) + " allow";
    }
    note += "); projected onto the nearest rotation (largest change of an entry " +
            Scientific(matrices_.change) + ")";
    notes.push_back(std::move(note));
  }
  if (quaternions_.count > 0) {
    std::string note = source_ + ": " + std::to_string(quaternions_.count) + " of " +
                       std::to_string(quaternions_.total) + " " + whose +
                       "quaternions were not unit within 1e-6 (largest |norm - 1| " +
                       Scientific(quaternions_.error) + " at " + Where(quaternions_.place);
    if (quaternions_.error <= 3.0 * quaternions_.rounding) {
      note += ", within what entries printed to +-" + Scientific(quaternions_.rounding) + " allow";
    }
    note += "); normalised";
    notes.push_back(std::move(note));
  }
  return notes;
}

}  // namespace hecal::io
