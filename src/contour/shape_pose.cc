// The job of `hecal contour pose`: see shape_pose.h.
#include "hecal/contour/shape_pose.h"

#include <string>

#include "hecal/core/error.h"

namespace hecal::contour {

ShapePose EstimateShapePose(const Vector6d& shape, const ShapePoseOptions& options) {
  ValidateContourCamera(options.camera);
  ShapePose result;
  result.pose = PoseFromShape(shape, options.camera, options.form);
  if (options.shape_covariance) {
    std::string why;
    if (!options.unscented.unscented.IsValid(6, &why)) {
      throw InputError("unscented", 0, why, "give a centre weight w0 < 1 (default 0)");
    }
    result.uncertainty = UnscentedPose(shape, *options.shape_covariance, options.camera,
                                       options.form, options.unscented);
  }
  return result;
}

}  // namespace hecal::contour
