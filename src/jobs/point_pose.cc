// The job of `hecal pose`: see point_pose.h.
#include "hecal/jobs/point_pose.h"

#include <array>
#include <cmath>
#include <map>
#include <string_view>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/point_file.h"

namespace hecal::jobs {
namespace {

struct Correspondences {
  std::vector<Eigen::Vector3d> object;  // metres
  std::vector<Eigen::Vector2d> pixels;
  std::vector<const io::PointRow*> image_rows;  // the image row of each pair (id, line)
};

Correspondences Pair(const io::PointFile& object, const io::PointFile& image) {
  Correspondences pairs;
  const auto add = [&](const io::PointRow& o, const io::PointRow& i) {
    pairs.object.push_back(o.value);
    pairs.pixels.push_back(i.value.head<2>());
    pairs.image_rows.push_back(&i);
  };
  if (object.has_ids && image.has_ids) {
    std::map<std::string, const io::PointRow*> by_id;
    for (const io::PointRow& row : object.rows) by_id.emplace(*row.id, &row);
    for (const io::PointRow& row : image.rows) {
      const auto it = by_id.find(*row.id);
      if (it == by_id.end()) {
        throw InputError(image.source, row.line,
                         "image point id '" + *row.id + "' is not in " + object.source,
                         "use the ids of the object points (or remove the id columns to pair by "
                         "order)");
      }
      add(*it->second, row);
    }
    return pairs;
  }
  if (object.rows.size() != image.rows.size()) {
    throw InputError(
        image.source, 0,
        std::to_string(image.rows.size()) + " image points but " +
            std::to_string(object.rows.size()) + " object points in " + object.source +
            " (paired by order: " +
            (object.has_ids || image.has_ids ? "only one file has ids" : "neither file has ids") +
            ")",
        "give one image point per object point in the same order, or ids in both "
        "files");
  }
  for (std::size_t k = 0; k < object.rows.size(); ++k) add(object.rows[k], image.rows[k]);
  return pairs;
}

// Every pixel must have a ray in this camera (strong distortion folds far outside the image).
void CheckRays(const Correspondences& pairs, const pose::CameraModel& camera,
               const std::string& source) {
  for (std::size_t k = 0; k < pairs.pixels.size(); ++k) {
    if (!pose::Undistort(camera, pairs.pixels[k])) {
      throw InputError(source, pairs.image_rows[k]->line,
                       "this pixel cannot be undistorted: the camera's distortion model has no "
                       "physical ray there",
                       "check the intrinsics (distortion coefficients) or remove the point");
    }
  }
}

}  // namespace

bool PointPoseOptions::IsValid(std::string* why) const {
  if (intrinsics.empty() == !focal.has_value()) {
    return Invalid(why, "PointPoseOptions.focal", "give exactly one of focal and intrinsics",
                   "a camera file for a calibrated camera, or the focal length F (px) for the "
                   "linear pose paper's pinhole without distortion");
  }
  if (focal && !(std::isfinite(*focal) && *focal > 0.0)) {
    return Invalid(why, "PointPoseOptions.focal",
                   "expected a positive number, got '" + io::FormatDouble(*focal) + "'",
                   "give the focal length in px");
  }
  if (principal_point) {
    if (!intrinsics.empty()) {
      return Invalid(why, "PointPoseOptions.principal_point",
                     "the principal point comes from the camera file", "leave it out");
    }
    if (!principal_point->allFinite()) {
      return Invalid(why, "PointPoseOptions.principal_point", "must be finite",
                     "give CX,CY in pixels");
    }
  }
  if (pixel_sigma && !(*pixel_sigma > 0.0 && *pixel_sigma <= kMaxPixelSigma)) {
    return Invalid(why, "PointPoseOptions.pixel_sigma",
                   "must be above 0 to " + io::FormatDouble(kMaxPixelSigma) + " px, got " +
                       io::FormatDouble(*pixel_sigma),
                   "give the noise of one image coordinate in pixels, e.g. 0.5");
  }
  return true;
}

PointPoseResult EstimatePoseFromFiles(const PointPoseOptions& options) {
  RequireValid(options);
  PointPoseResult result;
  pose::CameraModel camera;
  if (!options.intrinsics.empty()) {
    io::CameraFile file = io::ReadCameraFile(options.intrinsics);
    result.camera_notes = std::move(file.notes);
    camera = file.camera;
  } else {
    camera = pose::CameraModel::Pinhole(*options.focal);
    if (options.principal_point) {
      camera.cx = options.principal_point->x();
      camera.cy = options.principal_point->y();
    }
  }
  constexpr std::array<std::string_view, 3> kObjectColumns = {"x", "y", "z"};
  constexpr std::array<std::string_view, 2> kImageColumns = {"u", "v"};
  const io::PointFile object =
      io::ReadPointFile(options.points, kObjectColumns, true, options.units, "object points");
  const io::PointFile image = io::ReadPointFile(options.image_points, kImageColumns, false,
                                                io::LengthUnit::kMetre, "image points");
  const Correspondences pairs = Pair(object, image);
  CheckRays(pairs, camera, image.source);

  pose::PoseOptions pose_options;
  pose_options.refinement.pixel_sigma = options.pixel_sigma;
  result.estimate =
      options.solver
          ? options.solver(pairs.object, pairs.pixels, camera, pose_options)
          : pose::EstimatePose(options.method, pairs.object, pairs.pixels, camera, pose_options);
  for (const io::PointRow* row : pairs.image_rows) result.point_ids.push_back(row->id);
  result.unit = object.unit;
  result.points = pairs.object.size();
  return result;
}

}  // namespace hecal::jobs
