#include "hecal/report/page_thumbnails.h"

#include <gtest/gtest.h>

namespace hecal::report {
namespace {

TEST(PageThumbnails, DataUrisInBase64) {
  // RFC 4648 §10's test vectors, one per padding case.
  const nlohmann::json j =
      ThumbnailsJson({{"a", "f"}, {"b", "fo"}, {"c", "foo"}, {"d", "foobar"}}, 7);
  EXPECT_EQ(j["by_id"]["a"], "data:image/jpeg;base64,Zg==");
  EXPECT_EQ(j["by_id"]["b"], "data:image/jpeg;base64,Zm8=");
  EXPECT_EQ(j["by_id"]["c"], "data:image/jpeg;base64,Zm9v");
  EXPECT_EQ(j["by_id"]["d"], "data:image/jpeg;base64,Zm9vYmFy");
  EXPECT_EQ(j["count"], 4);
  EXPECT_EQ(j["images"], 7);
  EXPECT_EQ(j["bytes"], 4 * 23 + 4 + 4 + 4 + 8);
}

}  // namespace
}  // namespace hecal::report
