// The robustness corpus (ctest labels "robustness" and "unit"): every case of
// tests/data/robustness/cases.txt runs through RunHecal in one folder laid out below, and must
// exit with its code, print one line on stderr ("hecal: …") holding its text, and leave the
// folder exactly as it was — every entry's name, kind, link target and contents (a snapshot
// before and after each case), and /dev/null and /dev/full still character devices. The cases
// are bad input of every class (docs/reliability.md): outputs that are inputs, devices, pipes,
// folders or in missing folders; inputs that are not files; numbers out of range; images that
// are too small, too large or corrupt; inputs that drive a solver to non-finite values.
//
// The folder: robot.csv, camera.csv (pose tables); hard.csv (a hard link to robot.csv);
// link.csv → robot.csv, broken.csv → nothing, null-link → /dev/null (symbolic links); pipe (a
// FIFO); folder/, frames/init.csv/, det.points.csv/, est.camera.yaml/ (folders where files would
// go); keep.txt; p.json (data/moveit-calibration/pose_samples.json); robot16.txt (3 rows of 16
// numbers); colmajor.txt (a 4×4 written by columns); contour.csv; object.csv, image.csv;
// target.yaml (the rwhe-kuka2 chessboard); board9x6.yaml, board25x18.yaml, square_m.yaml,
// grid1.yaml (wrong descriptions of it: a 9 × 6 board, its squares counted instead of its inner
// corners, the square in mm read as m, a grid of one marker); grid_photo/
// (data/moveit-calibration's photo of a 3 × 4 DICT_4X4_250 ArUco grid), grid4x3.yaml and
// grid_dict.yaml (wrong descriptions of it: the layout its upstream test declares, and the
// dictionary DICT_5X5_250); k1.yaml (intrinsics with k1 = 1e6); images3/ (3 rwhe-kuka2 images);
// kuka_mm.txt (the rwhe-kuka2 robot poses with their translations × 1000); one_pixel/ (1×1 PNGs),
// huge/ (PNG headers of 12000×12000), truncated_jpeg/ (JPEGs cut in half), corrupt_jpeg/ (a JPEG
// with a stray marker in its scan), not_image/ (text named .png), cut_png/ (a PNG cut inside its
// header).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <opencv2/imgcodecs.hpp>
#endif

namespace hecal::cli {
namespace {

namespace fs = std::filesystem;
using cli_test::Hecal;
using cli_test::Outcome;

const std::string kSource = HECAL_SOURCE_DIR;

struct Case {
  int line = 0;
  int code = 0;
  std::string text;
  std::vector<std::string> args;
};

std::string Trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::vector<Case> ReadCases() {
  std::ifstream in(kSource + "/tests/data/robustness/cases.txt");
  EXPECT_TRUE(in) << "cannot open the corpus";
  std::vector<Case> cases;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (Trim(line).empty() || Trim(line)[0] == '#') continue;
    const auto bar1 = line.find('|');
    const auto bar2 = line.find('|', bar1 + 1);
    EXPECT_NE(bar2, std::string::npos) << "line " << number << ": " << line;
    if (bar2 == std::string::npos) continue;
    Case c;
    c.line = number;
    c.code = std::stoi(Trim(line.substr(0, bar1)));
    c.text = Trim(line.substr(bar1 + 1, bar2 - bar1 - 1));
    std::istringstream words(line.substr(bar2 + 1));
    for (std::string word; words >> word;) {
      const auto at = word.find("{data}");
      if (at != std::string::npos) word.replace(at, 6, kSource + "/data");
      c.args.push_back(word);
    }
    cases.push_back(c);
  }
  return cases;
}

// Every entry under `root`: relative name, kind, link target, size and a hash of the contents.
std::string Snapshot(const fs::path& root) {
  std::vector<std::string> entries;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    const fs::path& path = it->path();
    std::string entry = path.lexically_relative(root).string() + " ";
    const fs::file_status status = fs::symlink_status(path);
    if (fs::is_symlink(status)) {
      entry += "link " + fs::read_symlink(path).string();
    } else if (fs::is_directory(status)) {
      entry += "dir";
    } else if (fs::is_fifo(status)) {
      entry += "fifo";
    } else if (fs::is_regular_file(status)) {
      std::ifstream in(path, std::ios::binary);
      std::ostringstream contents;
      contents << in.rdbuf();
      entry += "file " + std::to_string(contents.str().size()) + " " +
               std::to_string(std::hash<std::string>{}(contents.str()));
    } else {
      entry += "other";
    }
    entries.push_back(entry);
  }
  std::sort(entries.begin(), entries.end());
  std::string text;
  for (const std::string& e : entries) text += e + "\n";
  return text;
}

bool IsCharacterDevice(const char* path) {
  struct stat info;
  return lstat(path, &info) == 0 && S_ISCHR(info.st_mode);
}

class RobustnessCorpus : public cli_test::CliTest {
 protected:
  void Copy(const fs::path& from, const std::string& to) const {
    fs::create_directories(fs::path(Path(to)).parent_path());
    fs::copy_file(from, Path(to));
  }

#if defined(HECAL_HAVE_OPENCV_PEERS)
  void WriteBytes(const std::string& name, const std::vector<unsigned char>& bytes) const {
    fs::create_directories(fs::path(Path(name)).parent_path());
    Write(name, std::string(bytes.begin(), bytes.end()));
  }

  void LayOut() const {
    const std::string poses =
        "id,x,y,z,qw,qx,qy,qz\n1,0.1,0,0,1,0,0,0\n2,0,0.1,0,0.9950042,0.0998334,0,0\n"
        "3,0,0,0.1,0.9950042,0,0.0998334,0\n4,0.1,0.1,0,0.9950042,0,0,0.0998334\n";
    Write("robot.csv", poses);
    Write("camera.csv", poses);
    fs::create_hard_link(Path("robot.csv"), Path("hard.csv"));
    fs::create_symlink("robot.csv", Path("link.csv"));
    fs::create_symlink("missing.csv", Path("broken.csv"));
    fs::create_symlink("/dev/null", Path("null-link"));
    ASSERT_EQ(mkfifo(Path("pipe").c_str(), 0600), 0);
    for (const char* folder : {"folder", "frames/init.csv", "det.points.csv", "est.camera.yaml"}) {
      fs::create_directories(Path(folder));
    }
    Write("keep.txt", "keep\n");
    Copy(kSource + "/data/moveit-calibration/pose_samples.json", "p.json");
    std::string row16;
    for (int i = 0; i < 16; ++i) row16 += (i % 5 == 0 ? "1 " : "0 ");
    Write("robot16.txt", row16 + "\n" + row16 + "\n" + row16 + "\n");
    Write("colmajor.txt", "0 1 0 0 -1 0 0 0 0 0 1 0 0.1 0.2 0.3 1\n");
    Write("contour.csv", "x,y\n0,0\n100,0\n100,100\n0,100\n");
    Write("object.csv", "id,x,y,z\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,1,1,0\n");
    Write("image.csv", "id,u,v\n1,0,0\n2,10,0\n3,0,10\n4,10,10\n");
    Copy(kSource + "/data/rwhe-kuka2/target.yaml", "target.yaml");
    // Plausible but wrong descriptions of the rwhe-kuka2 board (24 x 17 inner corners, 15 mm).
    Write("board9x6.yaml", "type: chessboard\ncols: 9\nrows: 6\nsquare: 15\nunits: mm\n");
    Write("board25x18.yaml", "type: chessboard\ncols: 25\nrows: 18\nsquare: 15\nunits: mm\n");
    Write("square_m.yaml", "type: chessboard\ncols: 24\nrows: 17\nsquare: 15\n");
    Write("grid1.yaml",
          "type: aruco_grid\ncols: 1\nrows: 1\nmarker: 0.05\nspacing: 0.01\n"
          "dictionary: DICT_4X4_50\n");
    Copy(kSource + "/data/moveit-calibration/test_aruco_marker_detection.png",
         "grid_photo/test_aruco_marker_detection.png");
    const std::string grid = "type: aruco_grid\nmarker: 0.0256\nspacing: 0.0066\n";
    Write("grid4x3.yaml", grid + "cols: 4\nrows: 3\ndictionary: DICT_4X4_250\n");
    Write("grid_dict.yaml", grid + "cols: 3\nrows: 4\ndictionary: DICT_5X5_250\n");
    Write("k1.yaml",
          "fx: 1000\nfy: 1000\ncx: 639.5\ncy: 479.5\ndistortion:\n  model: plumb_bob\n"
          "  coefficients: [1000000, 0, 0, 0, 0]\n");
    for (const char* image : {"im_01.png", "im_02.png", "im_03.png"}) {
      Copy(kSource + "/data/rwhe-kuka2/images/" + image, std::string("images3/") + image);
    }
    // The KUKA poses with the translation (elements 4, 8, 12 of each row-major 4×4) × 1000.
    std::ifstream kuka(kSource + "/data/rwhe-kuka2/RobotPosesVec.txt");
    std::string kuka_mm, line;
    while (std::getline(kuka, line)) {
      std::istringstream numbers(line);
      double value = 0.0;
      for (int i = 0; numbers >> value; ++i) {
        std::ostringstream number;
        number.precision(12);
        number << (i == 3 || i == 7 || i == 11 ? value * 1000.0 : value);
        kuka_mm += number.str() + (i == 15 ? "\n" : " ");
      }
    }
    Write("kuka_mm.txt", kuka_mm);

    std::vector<unsigned char> png, jpeg;
    ASSERT_TRUE(cv::imencode(".png", cv::Mat(1, 1, CV_8UC1, cv::Scalar(200)), png));
    cv::Mat gradient(64, 64, CV_8UC1);
    for (int y = 0; y < 64; ++y) {
      for (int x = 0; x < 64; ++x)
        gradient.at<unsigned char>(y, x) = static_cast<unsigned char>(x * 3 + y);
    }
    ASSERT_TRUE(cv::imencode(".jpg", gradient, jpeg));
    // A PNG header claiming 12000×12000 pixels (signature, IHDR, IEND; no pixel data).
    std::vector<unsigned char> huge = {0x89, 'P',  'N', 'G', '\r', '\n', 0x1a, '\n', 0,    0, 0,
                                       13,   'I',  'H', 'D', 'R',  0,    0,    0x2e, 0xe0, 0, 0,
                                       0x2e, 0xe0, 8,   0,   0,    0,    0,    0,    0,    0, 0};
    const std::vector<unsigned char> iend = {0,   0,   0,    0,    'I',  'E',
                                             'N', 'D', 0xae, 0x42, 0x60, 0x82};
    huge.insert(huge.end(), iend.begin(), iend.end());
    for (const char* name : {"a", "b", "c"}) {
      const std::string n = name;
      WriteBytes("one_pixel/" + n + ".png", png);
      WriteBytes("huge/" + n + ".png", huge);
      WriteBytes("truncated_jpeg/" + n + ".jpg",
                 std::vector<unsigned char>(jpeg.begin(), jpeg.begin() + jpeg.size() / 2));
    }
    // A marker in the middle of the scan, the end-of-image marker kept: libjpeg complains.
    std::vector<unsigned char> corrupt = jpeg;
    corrupt[corrupt.size() * 2 / 3] = 0xff;
    corrupt[corrupt.size() * 2 / 3 + 1] = 0xd4;
    WriteBytes("corrupt_jpeg/a.jpg", corrupt);
    WriteBytes("not_image/a.png", {'h', 'e', 'l', 'l', 'o', '\n'});
    WriteBytes("cut_png/a.png", std::vector<unsigned char>(png.begin(), png.begin() + 20));
  }
#endif
};

TEST_F(RobustnessCorpus, EveryCaseExitsWithItsReasonAndChangesNothing) {
#if !defined(HECAL_HAVE_OPENCV_PEERS)
  GTEST_SKIP() << "the corpus reads images: needs the vision layer";
#else
  LayOut();
  const std::vector<Case> cases = ReadCases();
  ASSERT_GE(cases.size(), 80u);
  const fs::path previous = fs::current_path();
  fs::current_path(dir_);
  for (const Case& c : cases) {
    std::string command;
    for (const std::string& a : c.args) command += " " + a;
    SCOPED_TRACE("cases.txt:" + std::to_string(c.line) + ": hecal" + command);
    const std::string before = Snapshot(dir_);
    const Outcome run = Hecal(c.args);
    EXPECT_EQ(run.code, c.code) << run.err;
    EXPECT_NE(run.err.find(c.text), std::string::npos) << run.err;
    EXPECT_EQ(run.err.rfind("hecal: ", 0), 0u) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(Snapshot(dir_), before);
    EXPECT_TRUE(IsCharacterDevice("/dev/null"));
    EXPECT_TRUE(IsCharacterDevice("/dev/full"));
  }
  fs::current_path(previous);
#endif
}

}  // namespace
}  // namespace hecal::cli
