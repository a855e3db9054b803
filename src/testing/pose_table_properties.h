// Test support (not installed): the properties every pose-table input must satisfy, shared by the
// libFuzzer target fuzz/fuzz_pose_table.cc and the replay of its findings
// (src/io/pose_table_fuzz_regression_test.cc over tests/data/fuzz-regressions/).
//
// For arbitrary bytes, ParsePoseTable either throws hecal::InputError or returns a table whose
// poses are finite rigid transforms; such a table writes in every rotation format and reads back
// to the same poses, ids and stamps, and pairs with itself. A violated property aborts (so the
// fuzzer records the input) after printing what failed.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/io/pose_table.h"

namespace hecal::testing {

inline void PropertyCheck(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "pose table property violated: %s\n", what);
    std::abort();
  }
}

// Reader options from one byte: bit 0 mm, bit 1 degrees, bit 2 invert, bits 3–7 an Euler
// sequence (0 = none, 1–24 = one of the 24 sequences).
inline io::PoseReadOptions PoseReadOptionsFromByte(uint8_t byte) {
  static constexpr const char* kSequences[] = {
      "xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz",
      "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"};
  io::PoseReadOptions options;
  options.units = (byte & 1) ? io::LengthUnit::kMillimetre : io::LengthUnit::kMetre;
  options.degrees = (byte & 2) != 0;
  options.invert = (byte & 4) != 0;
  const int sequence = byte >> 3;
  if (sequence >= 1 && sequence <= 24)
    options.euler = EulerSequence::Parse(kSequences[sequence - 1]);
  return options;
}

inline bool IsRigid(const Pose& pose) {
  if (!pose.matrix().allFinite()) return false;
  const Eigen::Matrix3d R = pose.linear();
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-9 &&
         std::abs(R.determinant() - 1.0) < 1e-9;
}

// Checks every property for one input; returns false when the input was (correctly) rejected.
inline bool CheckPoseTableProperties(std::string_view text, const io::PoseReadOptions& options) {
  io::PoseTable table;
  try {
    table = io::ParsePoseTable(text, "fuzz.csv", options);
  } catch (const InputError& error) {
    const std::string message = error.what();
    PropertyCheck(message.find('\n') == std::string::npos, "error message is one line");
    PropertyCheck(message.starts_with("fuzz.csv"), "error message names the file");
    return false;
  }
  PropertyCheck(!table.rows.empty(), "a table that parses has rows");
  double largest = 0.0;
  for (const io::PoseRow& row : table.rows) {
    PropertyCheck(IsRigid(row.pose), "every pose is a finite rigid transform");
    PropertyCheck(row.line >= 1, "rows know their line");
    if (row.stamp) PropertyCheck(std::isfinite(*row.stamp), "stamps are finite");
    largest = std::max(largest, row.pose.translation().cwiseAbs().maxCoeff());
  }

  static constexpr const char* kFormats[] = {"quaternion", "rotvec", "matrix", "kuka",
                                             "euler:zxz",  "abb",    "rpy"};
  for (const char* name : kFormats) {
    for (io::LengthUnit unit : {io::LengthUnit::kMetre, io::LengthUnit::kMillimetre}) {
      for (bool degrees : {false, true}) {
        io::PoseWriteOptions write;
        write.rotation = *io::ParseRotationFormat(name);
        write.units = unit;
        write.degrees = degrees;
        std::string written;
        try {
          written = io::FormatPoseTable(table, write);
        } catch (const InputError&) {
          // Only a position beyond what a double holds in millimetres may be refused.
          PropertyCheck(unit == io::LengthUnit::kMillimetre && largest > 1e300,
                        "every table can be written");
          continue;
        }
        io::PoseTable back;
        try {
          back = io::ParsePoseTable(written, "written.csv", {});
        } catch (const InputError& error) {
          std::fprintf(stderr, "%s\nwritten as %s:\n%s\n", error.what(), name, written.c_str());
          PropertyCheck(false, "a written table reads back");
        }
        PropertyCheck(back.rows.size() == table.rows.size(), "same number of rows");
        PropertyCheck(back.unit == unit, "same unit");
        // Euler angles within 1e-7 of gimbal lock reproduce R only to ~4e-7 (euler.h).
        const double rotation_tolerance =
            write.rotation.kind == io::RotationFormat::Kind::kEuler ? 1e-6 : 1e-12;
        for (size_t i = 0; i < table.rows.size(); ++i) {
          const io::PoseRow& a = table.rows[i];
          const io::PoseRow& b = back.rows[i];
          PropertyCheck(a.id == b.id, "ids survive");
          PropertyCheck(a.stamp == b.stamp, "stamps survive");
          const double rotation_error = (a.pose.linear() - b.pose.linear()).cwiseAbs().maxCoeff();
          PropertyCheck(rotation_error <= rotation_tolerance, "rotations survive");
          for (int k = 0; k < 3; ++k) {
            const double ta = a.pose.translation()[k];
            const double tb = b.pose.translation()[k];
            PropertyCheck(std::abs(ta - tb) <= 1e-15 * std::max(1.0, std::abs(ta)),
                          "translations survive");
          }
        }
      }
    }
  }
  const io::Stations stations = io::PairStations(table, table);
  PropertyCheck(stations.robot.size() == table.rows.size(), "a table pairs with itself");
  return true;
}

}  // namespace hecal::testing
