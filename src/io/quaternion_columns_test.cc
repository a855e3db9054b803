// HasQuaternionColumns on tables parsed from text written by hand: the quaternion header, and
// each of the other rotation layouts of docs/pose-files.md.
#include "hecal/io/quaternion_columns.h"

#include <gtest/gtest.h>

namespace hecal::io {
namespace {

bool QuaternionColumns(const char* text) {
  return HasQuaternionColumns(ParsePoseTable(text, "table.csv", {}));
}

TEST(QuaternionColumns, OnlyTheQuaternionHeaderHasThem) {
  EXPECT_TRUE(QuaternionColumns("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n"));
  EXPECT_FALSE(QuaternionColumns("x,y,z,rx,ry,rz\n0,0,0,0,0,0\n"));
  EXPECT_FALSE(
      QuaternionColumns("x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33\n"
                        "0,0,0,1,0,0,0,1,0,0,0,1\n"));
  EXPECT_FALSE(QuaternionColumns("1 0 0 0 0 1 0 0 0 0 1 0\n"));
}

}  // namespace
}  // namespace hecal::io
