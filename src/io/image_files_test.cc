// ListStationImages on folders laid out both ways (image_files.h): one image per station, or one
// sub-folder per station; which wins when both exist; the errors, each naming the folder at fault.
// Files are empty: listing reads no image.
#include "hecal/io/image_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "testing/thrown.h"

namespace hecal::io {
namespace {

// Each test in its own folder, removed afterwards.
class StationImagesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("hecal_image_files_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  // Creates the named files (empty, and their folders) under images/.
  std::string Folder(const std::vector<std::string>& files) {
    for (const std::string& file : files) {
      std::filesystem::create_directories((dir_ / "images" / file).parent_path());
      WriteFileAtomically(Path("images/" + file), "");
    }
    return Path("images");
  }

  std::filesystem::path dir_;
};

std::vector<std::string> Ids(const StationImages& listed) {
  std::vector<std::string> ids;
  for (const StationImage& station : listed.stations) ids.push_back(station.id);
  return ids;
}

TEST_F(StationImagesTest, OneImagePerStationInTheFolder) {
  const std::string dir = Folder({"im_10.png", "im_02.JPG", "notes.txt", "im_01.tiff"});
  const StationImages listed = ListStationImages(dir, "the target images");
  EXPECT_EQ(Ids(listed), (std::vector<std::string>{"im_01", "im_02", "im_10"}));
  EXPECT_FALSE(listed.sub_folders);
  EXPECT_TRUE(listed.note.empty());
  EXPECT_EQ(listed.stations[1].name, "im_02.JPG");
  EXPECT_EQ(listed.stations[1].path, std::filesystem::path(dir) / "im_02.JPG");
}

// The layout capture tools write: pose_NN/image.png beside the robot pose. Station ids are the
// sub-folder names, sorted; other files in a sub-folder are ignored, and so are hidden folders.
TEST_F(StationImagesTest, OneSubFolderPerStation) {
  const std::string dir =
      Folder({"pose_01/image.png", "pose_01/pose.yaml", "pose_00/image.png", "pose_10/capture.jpg",
              ".thumbnails/a.png", ".thumbnails/b.png", "readme.txt"});
  const StationImages listed = ListStationImages(dir, "the target images");
  EXPECT_TRUE(listed.sub_folders);
  EXPECT_EQ(Ids(listed), (std::vector<std::string>{"pose_00", "pose_01", "pose_10"}));
  EXPECT_EQ(listed.stations[2].name, "pose_10/capture.jpg");
  EXPECT_EQ(listed.stations[2].path, std::filesystem::path(dir) / "pose_10" / "capture.jpg");
  EXPECT_TRUE(listed.note.empty());
}

// Images at the top level win over sub-folders, with a note naming the sub-folders left out.
TEST_F(StationImagesTest, TopLevelImagesWinWithANote) {
  const std::string dir = Folder({"a.png", "b.png", "pose_00/image.png", "pose_01/image.png"});
  const StationImages listed = ListStationImages(dir, "the target images");
  EXPECT_FALSE(listed.sub_folders);
  EXPECT_EQ(Ids(listed), (std::vector<std::string>{"a", "b"}));
  EXPECT_NE(listed.note.find("2 image(s) and 2 sub-folder(s)"), std::string::npos) << listed.note;
  EXPECT_NE(listed.note.find("(pose_00, pose_01) are left out"), std::string::npos) << listed.note;
}

TEST_F(StationImagesTest, SubFoldersNeedExactlyOneImage) {
  std::string dir = Folder({"pose_00/image.png", "pose_01/left.png", "pose_01/right.png"});
  InputError error =
      testing::Thrown<InputError>([&] { ListStationImages(dir, "the target images"); });
  EXPECT_EQ(error.source(), (std::filesystem::path(dir) / "pose_01").string());
  EXPECT_NE(error.problem().find("holds 2 images (left.png, right.png)"), std::string::npos)
      << error.problem();
  EXPECT_NE(error.fix().find("keep one image in pose_01"), std::string::npos) << error.fix();

  std::filesystem::remove_all(dir_ / "images");
  dir = Folder({"pose_00/image.png", "pose_01/pose.yaml"});
  error = testing::Thrown<InputError>([&] { ListStationImages(dir, "the target images"); });
  EXPECT_EQ(error.source(), (std::filesystem::path(dir) / "pose_01").string());
  EXPECT_NE(error.problem().find("holds no image"), std::string::npos) << error.problem();
}

TEST_F(StationImagesTest, MissingOrEmptyFoldersAreErrors) {
  InputError error =
      testing::Thrown<InputError>([&] { ListStationImages(Path("nowhere"), "the target images"); });
  EXPECT_EQ(error.source(), Path("nowhere"));
  EXPECT_NE(error.problem().find("not a directory"), std::string::npos);

  const std::string dir = Folder({"notes.txt"});
  error = testing::Thrown<InputError>([&] { ListStationImages(dir, "the target images"); });
  EXPECT_EQ(error.source(), dir);
  EXPECT_NE(error.problem().find("no sub-folders with one each"), std::string::npos)
      << error.problem();
  // The plain lister (contour track) takes no sub-folders.
  Folder({"pose_00/image.png"});
  EXPECT_THROW(ListImageFiles(dir, "the image sequence"), InputError);
}

}  // namespace
}  // namespace hecal::io
