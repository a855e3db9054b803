#include "hecal/io/rotation_format.h"

#include <gtest/gtest.h>

namespace hecal::io {
namespace {

using Kind = RotationFormat::Kind;
using Strings = std::vector<std::string>;

RotationFormat ParseFormat(std::string_view text) {
  const std::optional<RotationFormat> format = ParseRotationFormat(text);
  EXPECT_TRUE(format.has_value()) << text;
  return format.value_or(RotationFormat{});
}

TEST(RotationFormatTest, PlainFormats) {
  const RotationFormat q = ParseFormat("quaternion");
  EXPECT_EQ(q.kind, Kind::kQuaternion);
  EXPECT_EQ(q.ColumnNames(), (Strings{"qw", "qx", "qy", "qz"}));
  EXPECT_FALSE(q.angles_in_degrees);

  const RotationFormat v = ParseFormat("rotvec");
  EXPECT_EQ(v.kind, Kind::kRotationVector);
  EXPECT_EQ(v.ColumnNames(), (Strings{"rx", "ry", "rz"}));

  const RotationFormat m = ParseFormat("matrix");
  EXPECT_EQ(m.kind, Kind::kMatrix);
  EXPECT_EQ(m.ColumnNames(),
            (Strings{"r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33"}));
}

TEST(RotationFormatTest, EulerSequencesKeepTheirCase) {
  const RotationFormat intrinsic = ParseFormat("euler:ZYX");
  EXPECT_EQ(intrinsic.kind, Kind::kEuler);
  ASSERT_TRUE(intrinsic.sequence);
  EXPECT_TRUE(intrinsic.sequence->intrinsic());
  EXPECT_EQ(intrinsic.sequence->ToString(), "ZYX");
  EXPECT_EQ(intrinsic.ColumnNames(), (Strings{"a1", "a2", "a3"}));

  const RotationFormat extrinsic = ParseFormat("EULER:zxz");
  ASSERT_TRUE(extrinsic.sequence);
  EXPECT_FALSE(extrinsic.sequence->intrinsic());
  EXPECT_TRUE(extrinsic.sequence->proper());
  EXPECT_EQ(extrinsic.ToString(), "euler:zxz");
}

TEST(RotationFormatTest, PresetsFollowDesignSection2) {
  const RotationFormat rpy = ParseFormat("rpy");
  EXPECT_EQ(rpy.kind, Kind::kEuler);
  EXPECT_EQ(rpy.sequence->ToString(), "xyz");
  EXPECT_FALSE(rpy.angles_in_degrees);
  EXPECT_EQ(rpy.ColumnNames(), (Strings{"roll", "pitch", "yaw"}));

  const RotationFormat kuka = ParseFormat("kuka");
  EXPECT_EQ(kuka.kind, Kind::kEuler);
  EXPECT_EQ(kuka.sequence->ToString(), "ZYX");
  EXPECT_TRUE(kuka.angles_in_degrees);
  EXPECT_EQ(kuka.ColumnNames(), (Strings{"a", "b", "c"}));

  const RotationFormat fanuc = ParseFormat("fanuc");
  EXPECT_EQ(fanuc.kind, Kind::kEuler);
  EXPECT_EQ(fanuc.sequence->ToString(), "xyz");
  EXPECT_TRUE(fanuc.angles_in_degrees);
  EXPECT_EQ(fanuc.ColumnNames(), (Strings{"w", "p", "r"}));

  const RotationFormat abb = ParseFormat("abb");
  EXPECT_EQ(abb.kind, Kind::kQuaternion);
  EXPECT_EQ(abb.ColumnNames(), (Strings{"q1", "q2", "q3", "q4"}));

  const RotationFormat ur = ParseFormat("ur");
  EXPECT_EQ(ur.kind, Kind::kRotationVector);
  EXPECT_FALSE(ur.angles_in_degrees);
  EXPECT_EQ(ur.ColumnNames(), (Strings{"rx", "ry", "rz"}));
}

TEST(RotationFormatTest, ToStringRoundTrips) {
  for (const char* text : {"quaternion", "rotvec", "matrix", "euler:ZYX", "euler:xyz", "euler:ZXZ",
                           "euler:yzy", "rpy", "kuka", "fanuc", "abb", "ur"}) {
    const RotationFormat format = ParseFormat(text);
    EXPECT_EQ(format.ToString(), text);
    EXPECT_EQ(ParseFormat(format.ToString()), format) << text;
  }
}

TEST(RotationFormatTest, NamesAreCaseInsensitive) {
  EXPECT_EQ(ParseFormat("Quaternion"), ParseFormat("quaternion"));
  EXPECT_EQ(ParseFormat("KUKA"), ParseFormat("kuka"));
}

TEST(RotationFormatTest, RejectsUnknownSpellings) {
  for (const char* text : {"", "quat", "euler", "euler:", "euler:xxy", "euler:XyZ", "euler:xy",
                           "euler:xyzz", "euler:abc", "kuka2", "matrix16", " rotvec"}) {
    EXPECT_FALSE(ParseRotationFormat(text).has_value()) << text;
  }
}

TEST(RotationFormatTest, SpellingsListEveryPreset) {
  const std::string_view spellings = RotationFormatSpellings();
  for (const char* name :
       {"quaternion", "rotvec", "matrix", "euler:", "rpy", "kuka", "fanuc", "abb", "ur"}) {
    EXPECT_NE(spellings.find(name), std::string_view::npos) << name;
  }
}

}  // namespace
}  // namespace hecal::io
