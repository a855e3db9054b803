// The image front end: see image_set.h.
#include "hecal/vision/image_set.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <opencv2/core/utility.hpp>

#include "hecal/core/error.h"
#include "hecal/core/limits.h"
#include "hecal/core/options_check.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/image_files.h"
#include "hecal/io/target_file.h"
#include "hecal/vision/image_read.h"
#include "hecal/vision/intrinsics_fit.h"
#include "hecal/vision/intrinsics_plausibility.h"
#include "hecal/vision/opencv_pnp.h"
#include "hecal/vision/order_consistency.h"
#include "hecal/vision/target_mismatch.h"
#include "size_text.h"

namespace hecal::vision {
namespace {

using io::FormatFixed;

// Hand–eye calibration needs 3 stations (2 motions); Zhang's intrinsics need 3 views; a pose
// with known intrinsics needs 1.
constexpr int kHandEyeStations = 3;
constexpr int kIntrinsicsViews = 3;

// The least number of usable images, and the rule that sets it, for messages.
struct ViewsNeeded {
  int count = 1;
  std::string rule;
};

ViewsNeeded Needed(const ImageSetOptions& options) {
  const bool estimate = options.intrinsics.empty();
  if (options.use == ImageUse::kHandEye) {
    return {kHandEyeStations, estimate ? "hand-eye calibration needs at least 3 stations (2 robot "
                                         "motions), and estimating the intrinsics 3 views"
                                       : "hand-eye calibration needs at least 3 stations (2 "
                                         "robot motions)"};
  }
  if (estimate) {
    return {kIntrinsicsViews,
            "estimating the intrinsics needs at least 3 views (with --intrinsics camera.yaml one "
            "view is enough)"};
  }
  return {1, "a pose needs the target in at least 1 view"};
}

std::vector<ImageRecord> Records(const io::StationImages& listed) {
  std::vector<ImageRecord> images;
  for (const io::StationImage& station : listed.stations) {
    ImageRecord record;
    record.path = station.path;
    record.station = station.id;
    record.name = station.name;
    images.push_back(std::move(record));
  }
  return images;
}

// Sets OpenCV's thread count for the command and restores it afterwards (tests run commands
// in-process).
class OpenCvThreads {
 public:
  explicit OpenCvThreads(int threads) : previous_(cv::getNumThreads()) {
    cv::setNumThreads(threads == 0 ? -1 : threads);  // -1: OpenCV's default, every core
  }
  ~OpenCvThreads() { cv::setNumThreads(previous_); }
  OpenCvThreads(const OpenCvThreads&) = delete;
  OpenCvThreads& operator=(const OpenCvThreads&) = delete;

 private:
  int previous_;
};

// Reads and detects every image, in parallel over images, with the given intrinsics when they
// are for the image's size (the intrinsics of another size are reported after the loop, by
// CheckIntrinsicsSize). A target description that an image shows to be wrong
// (vision/target_mismatch.h) is refused at once: the images after the first such one are not
// detected (those before it are, so that the error does not depend on the scheduling). Errors are
// raised after the loop, for the first image in file-name order.
void DetectAll(const pose::TargetSpec& target, const std::string& target_file,
               const std::optional<pose::CameraModel>& camera, std::vector<ImageRecord>* images) {
  std::vector<std::exception_ptr> errors(images->size());
  std::vector<TargetMismatch> wrong(images->size());
  const int none = static_cast<int>(images->size());
  std::atomic<int> first_wrong = none;
  cv::parallel_for_(
      cv::Range(0, static_cast<int>(images->size())),
      [&](const cv::Range& range) {
        for (int i = range.start; i < range.end; ++i) {
          if (i > first_wrong.load()) continue;
          ImageRecord& image = (*images)[static_cast<std::size_t>(i)];
          try {
            const cv::Mat pixels = ReadGrayImage(image.path.string(), kMinDetectionSide);
            image.size = pixels.size();
            const bool sized = camera && (camera->width <= 0 || (camera->width == pixels.cols &&
                                                                 camera->height == pixels.rows));
            image.detection = vision::DetectTarget(
                pixels, target, {}, sized ? camera : std::optional<pose::CameraModel>());
            TargetMismatch& mismatch = wrong[static_cast<std::size_t>(i)];
            mismatch = FindTargetMismatch(pixels, target, image.detection);
            for (int seen = first_wrong.load(); mismatch.found() && i < seen;) {
              if (first_wrong.compare_exchange_weak(seen, i)) break;
            }
          } catch (...) {
            errors[static_cast<std::size_t>(i)] = std::current_exception();
          }
        }
      },
      static_cast<double>(images->size()));
  for (std::size_t i = 0; i < images->size(); ++i) {
    if (static_cast<int>(i) == first_wrong.load()) {
      throw InputError(target_file, 0, "in " + (*images)[i].name + ", " + wrong[i].problem,
                       wrong[i].fix);
    }
    if (!errors[i]) continue;
    try {
      std::rethrow_exception(errors[i]);
    } catch (const InputError& e) {
      // DetectTarget's complaints about the target spec name "target": point at the file.
      if (e.source() == "target") throw InputError(target_file, 0, e.problem(), e.fix());
      throw;
    }
  }
}

void CheckSameSize(const std::vector<ImageRecord>& images) {
  const ImageRecord& first = images.front();
  for (const ImageRecord& image : images) {
    if (image.size != first.size) {
      throw InputError(image.path.string(), 0,
                       "the image is " + std::to_string(image.size.width) + "x" +
                           std::to_string(image.size.height) + " but " + first.name + " is " +
                           std::to_string(first.size.width) + "x" +
                           std::to_string(first.size.height),
                       "use images of one camera at one resolution");
    }
  }
}

// Half-turn ambiguous detections made consistent across the images (image rule); those that
// stay ambiguous, and every other unusable detection, get their reason in `skipped`.
void ResolveAndMarkUnusable(const pose::TargetSpec& target, std::vector<ImageRecord>* images) {
  std::vector<vision::Detection> detections;
  for (const ImageRecord& image : *images) detections.push_back(image.detection);
  vision::ResolveOrder(target, vision::OrderOptions{}, &detections);
  for (std::size_t i = 0; i < images->size(); ++i) {
    ImageRecord& image = (*images)[i];
    image.detection = std::move(detections[i]);
    if (image.detection.status == vision::DetectionStatus::kAmbiguous) {
      image.skipped =
          "point order undecided (a half-turn-symmetric pattern): " + image.detection.message;
    } else if (!image.detection.usable()) {
      image.skipped = image.detection.message;
    }
  }
}

int CountUsed(const std::vector<ImageRecord>& images) {
  return static_cast<int>(
      std::count_if(images.begin(), images.end(), [](const ImageRecord& i) { return i.used(); }));
}

// Enough usable images for the use (Needed), with a message that says what to check.
void CheckEnoughViews(const std::vector<ImageRecord>& images, const pose::TargetSpec& target,
                      const ImageSetOptions& options) {
  const int used = CountUsed(images);
  const ViewsNeeded needed = Needed(options);
  if (used >= needed.count) return;
  const bool none_seen = std::all_of(images.begin(), images.end(), [](const ImageRecord& i) {
    return i.detection.status == vision::DetectionStatus::kNotFound;
  });
  const std::string count = std::to_string(images.size()) + " image(s) in " + options.images;
  if (none_seen) {
    throw InputError(
        options.target, 0,
        "the target (" + Describe(target) + ") was found in none of the " + count,
        target.type == pose::TargetType::kChessboard
            ? "check cols/rows in target.yaml: cols/rows are INNER corners for a chessboard "
              "(a board of 25x18 squares has 24x17 inner corners)"
            : "check type, cols, rows and dictionary/family in target.yaml against the printed "
              "target");
  }
  throw InputError(
      options.images, 0,
      "the target is usable in only " + std::to_string(used) + " of the " + count,
      needed.rule + ": add images with the whole target visible and sharp, and check " +
          (pose::IsSingleTag(target.type)
               ? "the tag's id and family/dictionary in " + options.target
               : "cols/rows in " + options.target +
                     " (a board of the wrong size may be found in part of some images)"));
}

// The camera file's width × height against the images': equal, or an error naming both. Two
// mismatches are named as what they most likely are: the images turned a quarter turn, or the
// images resized by one factor (then the scaled intrinsics are given; pixel centres at integers,
// so c' = (c + ½)·s − ½).
void CheckIntrinsicsSize(const pose::CameraModel& camera, const std::string& path, cv::Size size) {
  if (camera.width <= 0 || (camera.width == size.width && camera.height == size.height)) return;
  const std::string sizes =
      "the intrinsics are for " + internal::SizeText(camera.width, camera.height) +
      " images but the images are " + internal::SizeText(size.width, size.height);
  if (camera.width == size.height && camera.height == size.width) {
    throw InputError(path, 0, sizes + ": the images are turned a quarter turn",
                     "use the images as the camera delivers them (undo the rotation, e.g. an "
                     "EXIF orientation applied on export), or calibrate the turned camera");
  }
  const double s = static_cast<double>(size.width) / camera.width;
  if (std::abs(camera.height * s - size.height) <= 1.0) {
    const auto scaled = [s](double c) { return (c + 0.5) * s - 0.5; };
    throw InputError(
        path, 0,
        sizes + ": the same aspect ratio, so the images look resized by " + FormatFixed(s, 4),
        "give the intrinsics of this resolution: if the images are the camera's, scaled, they are "
        "fx " +
            FormatFixed(camera.fx * s, 3) + ", fy " + FormatFixed(camera.fy * s, 3) + ", cx " +
            FormatFixed(scaled(camera.cx), 3) + ", cy " + FormatFixed(scaled(camera.cy), 3) +
            ", width " + std::to_string(size.width) + ", height " + std::to_string(size.height) +
            " (distortion unchanged); a lower-resolution camera mode may crop as well, so "
            "calibrating at this resolution is safer");
  }
  throw InputError(path, 0, sizes,
                   "use the intrinsics of this camera at this resolution, or leave out "
                   "--intrinsics to estimate them from the images");
}

// Distortion coefficients that move the image corner farther than 10 image diagonals (e.g.
// k1 = 1e6 for 1e-6, or a coefficient in the wrong slot) describe no lens: every pose from them
// would be nonsense ("behind the camera"), so they are refused naming the coefficients. The
// displacement of the corner farthest from the principal point, at normalised radius r, is
// bounded by |k1 r² + k2 r⁴ + k3 r⁶| r + 3 (|p1| + |p2|) r² (normalised), times fx in pixels.
void CheckDistortionRange(const pose::CameraModel& camera, const std::string& path, cv::Size size) {
  const double x = std::max(camera.cx, size.width - 1.0 - camera.cx) / camera.fx;
  const double y = std::max(camera.cy, size.height - 1.0 - camera.cy) / camera.fy;
  const double r2 = x * x + y * y;
  const auto& d = camera.distortion;  // k1, k2, p1, p2, k3
  const double radial = d[0] * r2 + d[1] * r2 * r2 + d[4] * r2 * r2 * r2;
  const double shift_px =
      (std::abs(radial) * std::sqrt(r2) + 3.0 * (std::abs(d[2]) + std::abs(d[3])) * r2) * camera.fx;
  const double diagonal = std::hypot(size.width, size.height);
  if (std::isfinite(shift_px) && shift_px <= 10.0 * diagonal) return;
  throw InputError(path, 0,
                   "the distortion (k1 " + io::FormatDouble(d[0]) + ", k2 " +
                       io::FormatDouble(d[1]) + ", p1 " + io::FormatDouble(d[2]) + ", p2 " +
                       io::FormatDouble(d[3]) + ", k3 " + io::FormatDouble(d[4]) +
                       ") would move the image corner by " + FormatFixed(shift_px, 0) +
                       " px, more than 10 image diagonals: no lens distorts like that",
                   "check the coefficients and their order (k1 k2 p1 p2 k3, OpenCV's "
                   "plumb_bob; a typo in an exponent?), or leave out --intrinsics to estimate "
                   "them");
}

// The points of every used image, one view each.
std::vector<vision::CalibrationView> UsedViews(const std::vector<ImageRecord>& images,
                                               const std::vector<pose::ObjectPoint>& board) {
  std::vector<vision::CalibrationView> views;
  for (const ImageRecord& image : images) {
    if (!image.used()) continue;
    views.push_back({ObjectPointsOf(image.detection, board), PixelsOf(image.detection)});
  }
  return views;
}

// The intrinsics estimated from the used images; refused when the target is nearly parallel in
// all of them, or when the estimate is no camera (intrinsics_plausibility.h: the points are not
// those of the described target, so the refusal names the target file).
vision::IntrinsicsResult EstimateIntrinsics(const std::vector<ImageRecord>& images,
                                            const std::vector<pose::ObjectPoint>& board,
                                            cv::Size size, const std::string& target_file) {
  const std::vector<vision::CalibrationView> views = UsedViews(images, board);
  vision::IntrinsicsResult result;
  try {
    result = vision::CalibrateIntrinsics(views, size.width, size.height);
  } catch (const DegenerateError& e) {
    throw InputError("--intrinsics", 0,
                     "cannot estimate the intrinsics from the " + std::to_string(views.size()) +
                         " usable images (" + e.what() + ")",
                     "give --intrinsics camera.yaml, or images with the target tilted "
                     "differently in each");
  }
  // Nearly parallel boards leave focal length and distance confounded; calibrateCamera's σ do
  // not show it (intrinsics_calibration.h), so the estimate is refused rather than used.
  const vision::IntrinsicsOptions defaults;
  if (result.normal_spread_deg < defaults.min_normal_spread_deg) {
    throw InputError("--intrinsics", 0,
                     "cannot estimate the intrinsics: the target is nearly parallel in all " +
                         std::to_string(views.size()) + " usable images (normals within " +
                         FormatFixed(result.normal_spread_deg, 1) +
                         " deg), so focal length and distance are confounded",
                     "give --intrinsics camera.yaml, or add images with the target tilted by "
                     "20-45 deg in different directions");
  }
  const vision::IntrinsicsPlausibility plausibility = vision::CheckIntrinsicsPlausible(result);
  if (!plausibility.plausible()) {
    std::string problems;
    for (const std::string& problem : plausibility.problems) {
      problems += (problems.empty() ? "" : "; ") + problem;
    }
    throw InputError(target_file, 0,
                     "the detected points do not fit one camera: the intrinsics estimated from "
                     "the " +
                         std::to_string(views.size()) + " usable images give " + problems,
                     "check cols, rows and square against the print: the board in these images "
                     "may be larger than described (cols/rows count INNER corners: a board of "
                     "25x18 squares has 24x17)");
  }
  return result;
}

// LM-refined pose of every used image; an image whose pose fails is skipped with the reason.
void EstimatePoses(const std::vector<pose::ObjectPoint>& board, const pose::CameraModel& camera,
                   std::vector<ImageRecord>* images) {
  for (ImageRecord& image : *images) {
    if (!image.used()) continue;
    const std::vector<Eigen::Vector3d> object = ObjectPointsOf(image.detection, board);
    const std::vector<Eigen::Vector2d> pixels = PixelsOf(image.detection);
    try {
      const Pose start = vision::SolvePnPOpenCvRefined(object, pixels, camera);
      image.pose = pose::RefinePose(start, object, pixels, camera);
    } catch (const DegenerateError& e) {
      image.skipped = std::string("no pose: ") + e.what();
    }
  }
}

// What vision::CheckIntrinsicsFit's correction says, as a sentence: the likely mistake and how
// well the images fit without it.
std::string CorrectionText(const vision::IntrinsicsCorrection& correction,
                           const pose::CameraModel& given, cv::Size size) {
  using Kind = vision::IntrinsicsCorrection::Kind;
  const pose::CameraModel& c = correction.camera;
  const std::string fits = " the images fit to " + FormatFixed(correction.median_rms_px, 3) + " px";
  switch (correction.kind) {
    case Kind::kSwapPrincipalPoint:
      return "cx and cy look swapped: with cx " + FormatFixed(c.cx, 2) + ", cy " +
             FormatFixed(c.cy, 2) + fits;
    case Kind::kScaleFocal:
      return "fx, fy look " + FormatFixed(1.0 / correction.scale, 3) +
             " times too large (a focal length of another lens, or in other units): with fx " +
             FormatFixed(c.fx, 1) + ", fy " + FormatFixed(c.fy, 1) + fits;
    case Kind::kScaleResolution:
      return "they look like the intrinsics of images " + FormatFixed(1.0 / correction.scale, 3) +
             " times this size (about " +
             internal::SizeText(static_cast<int>(std::lround(size.width / correction.scale)),
                                static_cast<int>(std::lround(size.height / correction.scale))) +
             "): scaled to these " + internal::SizeText(size.width, size.height) + " images (fx " +
             FormatFixed(c.fx, 1) + ", fy " + FormatFixed(c.fy, 1) + ", cx " +
             FormatFixed(c.cx, 1) + ", cy " + FormatFixed(c.cy, 1) + ")" + fits;
    case Kind::kNoDistortion:
      return "the images look undistorted already (rectified), while the camera file has "
             "distortion k1 " +
             FormatFixed(given.distortion[0], 4) + ": without it" + fits;
  }
  return "";
}

// With given intrinsics: does the pose model fit the images (vision::CheckIntrinsicsFit)? A
// median reprojection RMS of 2 px or more is refused, a clear excess over the free homography's
// fit is a warning; both name the likely mistake.
void CheckIntrinsicsFitImages(const ImageSetOptions& options, ImageSet* set) {
  const vision::IntrinsicsFit fit =
      vision::CheckIntrinsicsFit(UsedViews(set->images, set->board), set->camera);
  if (fit.verdict == vision::IntrinsicsVerdict::kFits) return;
  std::string found = "median reprojection RMS " + FormatFixed(fit.median_rms_px, 2) + " px over " +
                      std::to_string(CountUsed(set->images)) + " image(s) with these intrinsics";
  if (fit.median_free_rms_px) {
    found += ", where a free homography fits the same points to " +
             FormatFixed(*fit.median_free_rms_px, 2) + " px";
  }
  std::string source = options.intrinsics;
  std::string fix;
  if (fit.correction) {
    fix =
        CorrectionText(*fit.correction, set->camera, set->size) + "; correct " + options.intrinsics;
  } else if (fit.points_do_not_fit) {
    source = options.target;
    found = "the detected points do not fit the target: " + found;
    fix = "check " + options.target +
          " against the print (cols/rows, lengths, first_id), that the target is flat, and the "
          "distortion coefficients in " +
          options.intrinsics;
  } else {
    fix = "check " + options.intrinsics +
          ": the intrinsics of another camera or resolution, fx/fy scaled, cx/cy swapped, or "
          "images resized or cropped; or leave out --intrinsics to estimate them from the images "
          "(3 or more)";
  }
  if (fit.verdict == vision::IntrinsicsVerdict::kDoesNotFit) {
    const std::string what = fit.points_do_not_fit && !fit.correction
                                 ? found
                                 : "the intrinsics do not fit the images: " + found;
    throw InputError(source, 0, what, fix);
  }
  set->fit_warning = source + ": the intrinsics fit the images poorly: " + found + " (" + fix + ")";
}

}  // namespace

std::string Describe(const pose::TargetSpec& target) {
  const std::string type(pose::TargetTypeName(target.type));
  if (pose::IsSingleTag(target.type)) {
    return type + " " +
           (target.type == pose::TargetType::kAruco ? target.dictionary : target.family) + " id " +
           std::to_string(target.id);
  }
  return type + " " + std::to_string(target.cols) + "x" + std::to_string(target.rows);
}

std::vector<Eigen::Vector3d> ObjectPointsOf(const vision::Detection& detection,
                                            const std::vector<pose::ObjectPoint>& board) {
  std::vector<Eigen::Vector3d> points;
  for (const vision::ImagePoint& p : detection.points) {
    points.push_back(board[static_cast<std::size_t>(p.id)].position);
  }
  return points;
}

std::vector<Eigen::Vector2d> PixelsOf(const vision::Detection& detection) {
  std::vector<Eigen::Vector2d> pixels;
  for (const vision::ImagePoint& p : detection.points) pixels.push_back(p.pixel);
  return pixels;
}

int ImageSet::CountUsed() const {
  return vision::CountUsed(images);
}

int ImagesNeeded(const ImageSetOptions& options) {
  return Needed(options).count;
}

bool ImageSetOptions::IsValid(std::string* why) const {
  if (images.empty()) {
    return Invalid(why, "ImageSetOptions.images", "no image folder given",
                   "give the folder of target images");
  }
  if (target.empty()) {
    return Invalid(why, "ImageSetOptions.target", "no target file given",
                   "give the target description, e.g. target.yaml (docs/targets.md)");
  }
  if (!ThreadCountValid(threads, "ImageSetOptions.threads", why)) return false;
  return true;
}

ImageSet DetectImageSet(const ImageSetOptions& options, const ImageSetProgress& progress) {
  RequireValid(options);
  const auto report = [](const std::function<void(const ImageSet&)>& stage, const ImageSet& set) {
    if (stage) stage(set);
  };
  ImageSet set;
  set.target = io::ReadTargetFile(options.target);
  set.board = pose::ObjectPoints(set.target);
  std::optional<io::CameraFile> given;
  if (!options.intrinsics.empty()) given = io::ReadCameraFile(options.intrinsics);
  if (!given && pose::IsSingleTag(set.target.type)) {
    throw InputError("--intrinsics", 0,
                     "a single tag (" + Describe(set.target) +
                         ") gives 4 points per image: too few to estimate the intrinsics and the "
                         "lens distortion",
                     "give --intrinsics camera.yaml (calibrate the camera first, e.g. with "
                     "hecal detect on images of a chessboard or ChArUco board)");
  }
  const io::StationImages listed = io::ListStationImages(options.images, "the target images");
  set.images = Records(listed);
  set.sub_folders = listed.sub_folders;
  set.listing_note = listed.note;
  report(progress.listed, set);
  {
    const OpenCvThreads threads(options.threads);
    DetectAll(set.target, options.target,
              given ? std::optional<pose::CameraModel>(given->camera) : std::nullopt, &set.images);
  }
  CheckSameSize(set.images);
  set.size = set.images.front().size;
  if (given) {
    CheckIntrinsicsSize(given->camera, options.intrinsics, set.size);
    CheckDistortionRange(given->camera, options.intrinsics, set.size);
  }
  ResolveAndMarkUnusable(set.target, &set.images);
  report(progress.detected, set);
  CheckEnoughViews(set.images, set.target, options);

  if (given) {
    set.camera = given->camera;
    set.camera_notes = given->notes;
  } else {
    set.estimated = EstimateIntrinsics(set.images, set.board, set.size, options.target);
    set.camera = set.estimated->camera;
  }
  report(progress.intrinsics, set);
  EstimatePoses(set.board, set.camera, &set.images);
  report(progress.posed, set);
  CheckEnoughViews(set.images, set.target, options);
  if (given) CheckIntrinsicsFitImages(options, &set);
  return set;
}

}  // namespace hecal::vision
