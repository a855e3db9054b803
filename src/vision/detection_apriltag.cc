// AprilTag grid and single-tag detection with libapriltag 3.3, and the tag families shared with
// the renderer (detection.h: corner order and id scheme).
#include <apriltag.h>
#include <tag16h5.h>
#include <tag25h9.h>
#include <tag36h10.h>
#include <tag36h11.h>
#include <tagCircle21h7.h>
#include <tagCircle49h12.h>
#include <tagCustom48h12.h>
#include <tagStandard41h12.h>
#include <tagStandard52h13.h>

#include <array>
#include <cstdlib>
#include <memory>
#include <string_view>

#include "detection_internal.h"
#include "hecal/core/error.h"

namespace hecal::vision::internal {
namespace {

struct FamilyFunctions {
  std::string_view name;
  apriltag_family_t* (*create)();
  void (*destroy)(apriltag_family_t*);
};

// Every family of pose::AprilTagFamilies().
constexpr std::array<FamilyFunctions, 9> kFamilies = {{
    {"tag16h5", tag16h5_create, tag16h5_destroy},
    {"tag25h9", tag25h9_create, tag25h9_destroy},
    {"tag36h10", tag36h10_create, tag36h10_destroy},
    {"tag36h11", tag36h11_create, tag36h11_destroy},
    {"tagCircle21h7", tagCircle21h7_create, tagCircle21h7_destroy},
    {"tagCircle49h12", tagCircle49h12_create, tagCircle49h12_destroy},
    {"tagCustom48h12", tagCustom48h12_create, tagCustom48h12_destroy},
    {"tagStandard41h12", tagStandard41h12_create, tagStandard41h12_destroy},
    {"tagStandard52h13", tagStandard52h13_create, tagStandard52h13_destroy},
}};

// libapriltag's corners run counter-clockwise in the image from the tag's bottom-left:
// p[0] bottom-left, p[1] bottom-right, p[2] top-right, p[3] top-left. hecal's corner k (aruco
// order: top-left, top-right, bottom-right, bottom-left) is p[3 − k].
constexpr int kAprilTagCornerOf[4] = {3, 2, 1, 0};
// libapriltag puts pixel centres at (x + 0.5, y + 0.5) (AprilRobotics/apriltag GitHub #121);
// OpenCV and hecal at (x, y).
constexpr double kPixelCentreOffset = 0.5;

struct DetectorDeleter {
  void operator()(apriltag_detector_t* detector) const { apriltag_detector_destroy(detector); }
};
struct DetectionsDeleter {
  void operator()(zarray_t* detections) const { apriltag_detections_destroy(detections); }
};
// libapriltag 3.3 exports apriltag_to_image but not image_u8_destroy (that is in
// libapriltag-utils); image_u8_create allocates the struct and its buffer with calloc, so they
// are released with free, as image_u8_destroy does.
struct ImageDeleter {
  void operator()(image_u8_t* image) const {
    std::free(image->buf);
    std::free(image);
  }
};

}  // namespace

AprilTagFamily::AprilTagFamily(const std::string& name) {
  for (const FamilyFunctions& functions : kFamilies) {
    if (functions.name == name) {
      family_ = functions.create();
      destroy_ = functions.destroy;
      return;
    }
  }
  throw InputError("target", 0, "unknown AprilTag family '" + name + "'",
                   "use one of libapriltag's families, e.g. tag36h11");
}

AprilTagFamily::~AprilTagFamily() {
  destroy_(family_);
}

int AprilTagFamily::total_width() const {
  return family_->total_width;
}

int AprilTagFamily::width_at_border() const {
  return family_->width_at_border;
}

cv::Mat AprilTagCells(const AprilTagFamily& family, int id) {
  const std::unique_ptr<image_u8_t, ImageDeleter> image(apriltag_to_image(family.get(), id));
  cv::Mat cells(image->height, image->width, CV_8U);
  for (int y = 0; y < image->height; ++y) {
    for (int x = 0; x < image->width; ++x) {
      cells.at<uchar>(y, x) = image->buf[y * image->stride + x] > 127 ? 1 : 0;
    }
  }
  return cells;
}

Detection DetectAprilTags(const cv::Mat& gray, const pose::TargetSpec& target,
                          const DetectOptions& options,
                          const std::optional<pose::CameraModel>& camera) {
  const MarkerGrid grid = MarkerGridOf(target);
  const AprilTagFamily family(target.family);
  const std::unique_ptr<apriltag_detector_t, DetectorDeleter> detector(apriltag_detector_create());
  apriltag_detector_add_family_bits(detector.get(), family.get(), options.apriltag_max_hamming);
  detector->quad_decimate = static_cast<float>(options.apriltag_decimate);
  detector->nthreads = 1;
  const cv::Mat contiguous = gray.isContinuous() ? gray : gray.clone();
  image_u8_t image{contiguous.cols, contiguous.rows, contiguous.cols,
                   const_cast<uint8_t*>(contiguous.ptr<uint8_t>())};
  const std::unique_ptr<zarray_t, DetectionsDeleter> found(
      apriltag_detector_detect(detector.get(), &image));

  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<int> ids;
  std::vector<int> others;
  const int markers = grid.cols * grid.rows;
  for (int k = 0; k < zarray_size(found.get()); ++k) {
    apriltag_detection_t* tag = nullptr;
    zarray_get(found.get(), k, &tag);
    if (tag->hamming > options.apriltag_max_hamming) continue;
    const int m = tag->id - grid.first_id;
    if (m < 0 || m >= markers) {
      others.push_back(tag->id);
      continue;
    }
    std::vector<cv::Point2f> quad;
    for (const int corner : kAprilTagCornerOf) {
      quad.emplace_back(static_cast<float>(tag->p[corner][0] - kPixelCentreOffset),
                        static_cast<float>(tag->p[corner][1] - kPixelCentreOffset));
    }
    corners.push_back(std::move(quad));
    ids.push_back(tag->id);
  }
  const std::string summary = KeepUniqueMarkers(&ids, &corners, "tags", others);
  RefineMarkerCorners(gray, family.width_at_border(), camera, &corners);
  std::vector<ImagePoint> points = GridMarkerPoints(ids, corners, grid.first_id);
  return MarkerDetection(gray, target, options, std::move(points), summary);
}

}  // namespace hecal::vision::internal
