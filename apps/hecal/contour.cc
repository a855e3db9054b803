// `hecal contour` and `hecal contour pose`: see contour.h.
#include "contour.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string_view>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/pose_uncertainty.h"
#include "hecal/contour/shape_pose.h"
#include "hecal/core/error.h"
#include "hecal/io/point_file.h"
#include "hecal/report/contour_pose_file.h"
#include "hecal/report/contour_pose_text.h"

namespace hecal::cli {
namespace {

Matrix6d ParseShapeCovariance(const std::string& text) {
  const std::size_t count = static_cast<std::size_t>(std::count(text.begin(), text.end(), ',')) + 1;
  if (count != 6 && count != 36) {
    throw InputError(
        "--covariance", 0,
        "expected 6 variances or 36 numbers (the row-major 6×6 Σ_S), got " + std::to_string(count),
        "give var(tx),…,var(m12), or all 36 entries");
  }
  const std::vector<double> v = ParseNumberList("--covariance", text, count, "Σ_S entries");
  Matrix6d C = Matrix6d::Zero();
  if (count == 6) {
    for (int i = 0; i < 6; ++i) C(i, i) = v[static_cast<std::size_t>(i)];
  } else {
    for (int i = 0; i < 36; ++i) C(i / 6, i % 6) = v[static_cast<std::size_t>(i)];
  }
  return C;
}

}  // namespace

contour::ContourCamera ParseContourCamera(const std::string& focal, const std::string& z0) {
  contour::ContourCamera camera;
  camera.focal = ParseNumber("--focal", focal, "the focal length");
  camera.z0 = ParseNumber("--z0", z0, "the initial distance Z0");
  contour::ValidateContourCamera(camera);
  return camera;
}

contour::RotationForm ParseRotationFlag(const std::string& text) {
  const std::optional<contour::RotationForm> form = contour::ParseRotationForm(text);
  if (!form) {
    throw InputError("--rotation", 0, "unknown rotation form '" + text + "'",
                     "use zyx (roll–pitch–yaw, the contour paper's choice) or zxz");
  }
  return *form;
}

Eigen::Matrix2Xd ReadContourFile(const std::string& path) {
  constexpr std::array<std::string_view, 2> kColumns = {"x", "y"};
  const io::PointFile file = io::ReadPointFile(path, kColumns, /*lengths=*/false,
                                               io::LengthUnit::kMetre, "contour points");
  if (file.rows.size() < 4) {
    throw InputError(path, 0,
                     "a closed contour needs at least 4 points, the file has " +
                         std::to_string(file.rows.size()),
                     "give the header x,y and then 4 or more points around the contour");
  }
  Eigen::Matrix2Xd Q(2, static_cast<Eigen::Index>(file.rows.size()));
  for (std::size_t i = 0; i < file.rows.size(); ++i) {
    Q.col(static_cast<Eigen::Index>(i)) = file.rows[i].value.head<2>();
  }
  return Q;
}

void RunContourPose(const ContourPoseOptions& options, const Io& io) {
  const std::vector<double> s =
      ParseNumberList("--shape", options.shape, 6, "tx,ty,m11m1,m22m1,m21,m12");
  const Vector6d shape = Eigen::Map<const Vector6d>(s.data());
  const contour::ContourCamera camera = ParseContourCamera(options.focal, options.z0);
  contour::ShapePoseOptions pose_options;
  pose_options.camera = camera;
  pose_options.form = ParseRotationFlag(options.rotation);
  if (!options.covariance.empty()) {
    const double w0 = ParseNumber("--ut-w0", options.ut_w0, "w0 < 1");
    pose_options.unscented.unscented = uncertainty::UnscentedParameters::Symmetric(w0);
    pose_options.shape_covariance = ParseShapeCovariance(options.covariance);
  }
  const contour::ShapePose result = contour::EstimateShapePose(shape, pose_options);
  if (options.json) {
    io.out << report::ContourPoseJson(result);
    return;
  }
  report::PrintContourPose(io.out, result);
}

void RegisterContourCommand(CLI::App& app, const Io& io) {
  CLI::App* contour = app.add_subcommand(
      "contour", "Camera motion from the affine deformation of a planar contour (docs/contour.md)");
  contour->require_subcommand(1);

  auto options = std::make_shared<ContourPoseOptions>();
  CLI::App* pose = contour->add_subcommand("pose", "The camera motion of one shape vector");
  pose->add_option("--shape", options->shape,
                   "tx,ty,m11m1,m22m1,m21,m12: S = (tx, ty, M11−1, M22−1, M21, M12), tx, ty in "
                   "the unit of --focal (use --shape=… when it starts with '-')")
      ->required()
      ->allow_extra_args(false);
  pose->add_option("--z0", options->z0, "Initial distance Z0 (the unit of the translation)")
      ->required();
  pose->add_option("--focal", options->focal, "Focal length F (the unit of tx, ty)")->required();
  pose->add_option("--rotation", options->rotation, "zyx (default; roll–pitch–yaw) or zxz");
  pose->add_flag("--json", options->json, "Print JSON");
  pose->add_option("--covariance", options->covariance,
                   "Σ_S: 6 variances or 36 row-major entries → UT pose covariance");
  pose->add_option("--ut-w0", options->ut_w0, "UT centre weight w0 (default 0)");
  pose->callback([options, io] { RunContourPose(*options, io); });

  AddContourStudyCommand(*contour, io);
  AddContourTrackCommand(*contour, io);
  AddContourRenderCommand(*contour, io);
}

}  // namespace hecal::cli
