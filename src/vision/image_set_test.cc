// ImageSetOptions::IsValid (core/options_check.h): the defaults with a folder and a target are
// valid; each checked field is refused with its name; DetectImageSet refuses them before it
// reads anything (the folder and target named here do not exist, so a later error would differ).
#include "hecal/vision/image_set.h"

#include <gtest/gtest.h>

#include "hecal/core/limits.h"
#include "testing/options_validity.h"

namespace hecal::vision {
namespace {

TEST(ImageSetOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  ImageSetOptions options;
  options.images = "no-such-folder";
  options.target = "no-such-target.yaml";
  EXPECT_TRUE(testing::IsValidOptions(options));
  ImageSetOptions most = options;
  most.threads = kMaxThreads;
  EXPECT_TRUE(testing::IsValidOptions(most));
  EXPECT_TRUE(RefusesNaming(options, "ImageSetOptions.images", [](auto& o) { o.images.clear(); }));
  EXPECT_TRUE(RefusesNaming(options, "ImageSetOptions.target", [](auto& o) { o.target.clear(); }));
  EXPECT_TRUE(RefusesNaming(options, "ImageSetOptions.threads", [](auto& o) { o.threads = -1; }));
  EXPECT_TRUE(RefusesNaming(options, "ImageSetOptions.threads",
                            [](auto& o) { o.threads = kMaxThreads + 1; }));
  options.threads = -1;
  try {
    DetectImageSet(options);
    ADD_FAILURE() << "accepted threads = -1";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "ImageSetOptions.threads");
  }
}

}  // namespace
}  // namespace hecal::vision
