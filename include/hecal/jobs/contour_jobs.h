// The contour methods' jobs in the front door (docs/contour.md): the camera motion of
// one shape vector with its Unscented-Transform covariance (`hecal contour pose`,
// contour/shape_pose.h) and the study of the pose error along a motion (`hecal contour study`,
// contour/contour_study.h). They are the contour module's own entry points — typed options with
// IsValid, a typed result — and their results are what report/contour_*.h format, so they stay
// in that module and are offered here by name. Tracking a contour through images and rendering
// a sequence are jobs of this layer (contour_tracking.h, contour_rendering.h).
#pragma once

#include "hecal/contour/contour_study.h"
#include "hecal/contour/sequence.h"
#include "hecal/contour/shape_pose.h"
#include "hecal/io/contour_file.h"

namespace hecal::jobs {

using contour::ContourStudyOptions;
using contour::EstimateShapePose;
using contour::RunContourStudy;
using contour::ShapePose;
using contour::ShapePoseOptions;
using contour::StudyStep;

}  // namespace hecal::jobs
