// The result files of `hecal contour track`: see contour_track_file.h.
#include "hecal/report/contour_track_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string_view>

#include "hecal/geometry/angle_units.h"
#include "hecal/io/delimited_text.h"
#include "hecal/report/json_matrix.h"
#include "hecal/version.h"

namespace hecal::report {
namespace {
constexpr std::array<std::string_view, 6> kShapeNames = {"tx",    "ty",  "m11m1",
                                                         "m22m1", "m21", "m12"};

}  // namespace

std::string ContourTrackCsv(const ContourTrack& track) {
  const contour::RotationForm form = track.options.form;
  const std::array<std::string_view, 6> names = contour::PoseParameterNames(form);
  std::string csv =
      "# hecal " + std::string(kVersion) +
      " contour track: S = (tx, ty, M11-1, M22-1, M21, M12), tx/ty in px; " +
      "translation in the unit of --z0 (Z0 = " + io::FormatDouble(track.options.camera.z0) +
      "); pose model " + (track.options.perspective ? "perspective" : "weak perspective") +
      "; angles in degrees (" + std::string(contour::RotationSequence(form)) +
      "); sd = 1 sigma (UT for the pose)\n";
  csv += "frame,image,status,edges_used,edges_searched,sigma_px,residual_rms_px";
  const auto column = [&csv](std::string_view prefix, std::string_view name,
                             std::string_view suffix) {
    csv.append(",").append(prefix).append(name).append(suffix);
  };
  for (std::string_view n : kShapeNames) column("", n, "");
  for (std::string_view n : kShapeNames) column("sd_", n, "");
  for (std::size_t i = 0; i < 6; ++i) column("", names[i], i < 3 ? "" : "_deg");
  for (std::size_t i = 0; i < 6; ++i) column("sd_", names[i], i < 3 ? "" : "_deg");
  csv += ",bias\n";
  for (const contour::TrackedImage& image : track.frames) {
    const contour::SequenceFrame& f = image.frame;
    const contour::TrackedFrame& t = f.tracked;
    csv += std::to_string(t.frame) + "," + io::QuoteField(image.image) + "," +
           std::string(contour::FrameStatusName(f.status)) + "," + std::to_string(t.edges_used) +
           "," + std::to_string(t.edges_searched) + ",";
    io::AppendDouble(t.sigma, &csv);
    csv += ",";
    io::AppendDouble(t.residual_rms, &csv);
    for (int i = 0; i < 6; ++i) {
      csv += ",";
      io::AppendDouble(t.shape(i), &csv);
    }
    for (int i = 0; i < 6; ++i) {
      csv += ",";
      io::AppendDouble(std::sqrt(std::max(0.0, t.shape_covariance(i, i))), &csv);
    }
    std::string biased;
    for (int i = 0; i < 12; ++i) {
      csv += ",";
      if (!f.pose) continue;
      const int j = i % 6;
      const double value =
          i < 6 ? f.pose->parameters(j) : std::sqrt(std::max(0.0, f.pose->covariance(j, j)));
      io::AppendDouble(j < 3 ? value : value * kDegreesPerRadian, &csv);
    }
    if (f.pose) {
      for (std::size_t j = 0; j < 6; ++j) {
        if (f.pose->biased[j]) biased.append(biased.empty() ? "" : " ").append(names[j]);
      }
    }
    csv.append(",").append(io::QuoteField(biased)).append("\n");
  }
  return csv;
}

std::string ContourTrackJson(const ContourTrack& track) {
  const contour::SequenceTrackingOptions& options = track.options;
  const std::array<std::string_view, 6> names = contour::PoseParameterNames(options.form);
  nlohmann::json parameter_names = nlohmann::json::array();
  for (std::string_view n : names) parameter_names.push_back(n);
  nlohmann::json shape_names = nlohmann::json::array();
  for (std::string_view n : kShapeNames) shape_names.push_back(n);
  nlohmann::json result = {
      {"hecal_version", kVersion},
      {"command", "contour track"},
      {"pose_model", options.perspective ? "perspective" : "weak"},
      {"units",
       {{"shape", "tx, ty in px (from the principal point); M entries dimensionless"},
        {"translation", "unit of --z0"},
        {"euler_deg", "deg"},
        {"pose_parameters", "translation in the unit of --z0, angles in rad"},
        {"pose_covariance", "over pose_parameters: (unit of --z0)^2, rad^2 and products"}}},
      {"camera",
       {{"focal_px", options.camera.focal},
        {"z0", options.camera.z0},
        {"principal_point", JsonVector(options.principal)}}},
      {"subspace", contour::ShapeSubspaceName(options.tracker.subspace)},
      {"rotation",
       {{"form", contour::RotationFormName(options.form)},
        {"sequence", contour::RotationSequence(options.form)}}},
      {"shape_names", shape_names},
      {"pose_parameter_names", parameter_names},
      {"template_shape", JsonVector(track.template_shape)},
      {"polarity", track.polarity},
  };
  nlohmann::json list = nlohmann::json::array();
  for (const contour::TrackedImage& image : track.frames) {
    const contour::SequenceFrame& f = image.frame;
    const contour::TrackedFrame& t = f.tracked;
    nlohmann::json frame = {
        {"frame", t.frame},
        {"image", image.image},
        {"status", contour::FrameStatusName(f.status)},
        {"edges",
         {{"searched", t.edges_searched}, {"found", t.edges_found}, {"used", t.edges_used}}},
        {"measurement_sigma_px", t.sigma},
        {"measurement_sigma_source", t.sigma_estimated ? "estimated" : "given"},
        {"residual_rms_px", t.residual_rms},
        {"shape", JsonVector(t.shape)},
        {"shape_covariance", JsonRows(t.shape_covariance)},
        {"x", JsonVector(t.x)},
        {"x_covariance", JsonRows(t.x_covariance)},
    };
    if (f.pose) {
      nlohmann::json bias = nlohmann::json::object();
      for (std::size_t j = 0; j < 6; ++j) bias[std::string(names[j])] = f.pose->biased[j];
      frame["pose"] = {
          {"translation", JsonVector(f.pose->pose.translation)},
          {"rotation_matrix", JsonRows(f.pose->pose.rotation)},
          {"euler_deg", JsonVector(f.pose->pose.euler * kDegreesPerRadian)},
          {"parameters", JsonVector(f.pose->parameters)},
          {"covariance", JsonRows(f.pose->covariance)},
          {"ut_mean", JsonVector(f.pose->mean)},
          {"bias", bias},
      };
    }
    list.push_back(std::move(frame));
  }
  result["frames"] = std::move(list);
  return result.dump(2) + "\n";
}

}  // namespace hecal::report
