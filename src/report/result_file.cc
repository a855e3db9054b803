#include "hecal/report/result_file.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/rotation.h"
#include "hecal/io/atomic_file.h"
#include "hecal/report/json_matrix.h"
#include "hecal/report/translation_sigma.h"
#include "hecal/report/yaml_tree.h"
#include "hecal/version.h"

namespace hecal::report {
namespace {

using nlohmann::json;

// A pose in the output length unit: 4×4 matrix, translation, Hamilton quaternion (w, x, y, z).
json PoseJson(const Pose& T, std::string_view frame, double scale) {
  Eigen::Matrix4d M = T.matrix();
  M.topRightCorner<3, 1>() *= scale;
  const Eigen::Quaterniond q = QuaternionFromMatrix(T.linear());
  const Eigen::Vector3d t = scale * T.translation();
  return {{"frame", frame},
          {"matrix", JsonRows(M)},
          {"translation", {t.x(), t.y(), t.z()}},
          {"quaternion_wxyz", {q.w(), q.x(), q.y(), q.z()}}};
}

// Right-perturbation covariance from metres to the output unit: translation rows/columns scale.
json CovarianceJson(const Matrix6d& covariance, double scale) {
  Vector6d s;
  s << 1.0, 1.0, 1.0, scale, scale, scale;
  // Written exactly symmetric (the solver's inverse is symmetric only to rounding).
  const Matrix6d scaled = s.asDiagonal() * covariance * s.asDiagonal();
  return JsonRows(0.5 * (scaled + scaled.transpose()));
}

// Per-axis values of a (ω, v) 6-vector of standard deviations: degrees and the output unit.
json SigmaJson(const Vector6d& sd, double scale) {
  const Eigen::Vector3d r = sd.head<3>() * kDegreesPerRadian;
  const Eigen::Vector3d t = sd.tail<3>() * scale;
  return {{"rotation_deg", {r.x(), r.y(), r.z()}}, {"translation", {t.x(), t.y(), t.z()}}};
}

// sigma.X / sigma.Z along the poses' own axes, and translation_in_parent along the axes their
// translations are written in (translation_sigma.h).
json CovarianceSectionJson(const estimation::CalibrationCovariance& c, handeye::Setup setup,
                           const Pose& X, const Pose& Z, double scale) {
  Eigen::Matrix<double, 12, 1> s;
  s << 1.0, 1.0, 1.0, scale, scale, scale, 1.0, 1.0, 1.0, scale, scale, scale;
  const Eigen::Matrix<double, 12, 12> scaled = s.asDiagonal() * c.covariance * s.asDiagonal();
  json section = {{"X", CovarianceJson(c.X(), scale)},
                  {"Z", CovarianceJson(c.Z(), scale)},
                  {"XZ", JsonRows(Matrix6d(scaled.topRightCorner<6, 6>()))},
                  {"parameterization", "right, (rx,ry,rz,tx,ty,tz)"},
                  {"method", estimation::CovarianceMethodName(c.method)},
                  {"solves", c.solves},
                  {"sigma",
                   {{"X", SigmaJson(c.X().diagonal().cwiseSqrt(), scale)},
                    {"Z", SigmaJson(c.Z().diagonal().cwiseSqrt(), scale)}}}};
  section["sigma"]["X"]["translation_in_parent"] =
      TranslationSigmaInParentJson(handeye::XFrameName(setup), X, c.X(), scale);
  section["sigma"]["Z"]["translation_in_parent"] =
      TranslationSigmaInParentJson(handeye::ZFrameName(setup), Z, c.Z(), scale);
  if (c.method == estimation::CovarianceMethod::kMonteCarlo) {
    section["samples"] = c.samples;
    section["failed_samples"] = c.failures;
    section["sigma_std_error"] = {{"X", SigmaJson(c.sd_std_error.head<6>(), scale)},
                                  {"Z", SigmaJson(c.sd_std_error.tail<6>(), scale)}};
  }
  return section;
}

// covariance.model_check (estimation/model_check.h): both sigmas per axis, their ratio, the
// check's relative sampling error, the factor on each σ when used, the flagged axes and whether
// the reported covariance is the inflated one.
json ModelCheckJson(const estimation::ModelCheck& check, double scale) {
  if (!check.possible)
    return {{"method", "jackknife"}, {"possible", false}, {"reason", check.reason}};
  const Eigen::Matrix<double, 12, 1> ratio = check.Ratio();
  json flagged = json::array();
  for (int k = 0; k < 12; ++k) {
    static const char* const kNames[6] = {"rx", "ry", "rz", "tx", "ty", "tz"};
    if (check.flagged[static_cast<size_t>(k)])
      flagged.push_back(std::string(k < 6 ? "X." : "Z.") + kNames[k % 6]);
  }
  auto per_axis = [](const Vector6d& v) {
    return json{{"rotation", {v(0), v(1), v(2)}}, {"translation", {v(3), v(4), v(5)}}};
  };
  return {{"method", "jackknife"},
          {"possible", true},
          {"groups", check.groups},
          {"sigma_model",
           {{"X", SigmaJson(check.sigma_model.head<6>(), scale)},
            {"Z", SigmaJson(check.sigma_model.tail<6>(), scale)}}},
          {"sigma_check",
           {{"X", SigmaJson(check.sigma_check.head<6>(), scale)},
            {"Z", SigmaJson(check.sigma_check.tail<6>(), scale)}}},
          {"ratio", {{"X", per_axis(ratio.head<6>())}, {"Z", per_axis(ratio.tail<6>())}}},
          {"relative_error",
           {{"X", per_axis(check.relative_error.head<6>())},
            {"Z", per_axis(check.relative_error.tail<6>())}}},
          {"inflation",
           {{"X", per_axis(check.Inflation().head<6>())},
            {"Z", per_axis(check.Inflation().tail<6>())}}},
          {"flagged", flagged},
          {"used", check.used}};
}

json CameraJson(const pose::CameraModel& camera) {
  return {{"fx", camera.fx},
          {"fy", camera.fy},
          {"cx", camera.cx},
          {"cy", camera.cy},
          {"width", camera.width},
          {"height", camera.height},
          {"distortion",
           {{"model", "plumb_bob"},
            {"coefficients",
             std::vector<double>(camera.distortion.begin(), camera.distortion.end())}}}};
}

json ImagesJson(const ResultDocument& document, const ImageReport& report) {
  const double scale = 1.0 / io::MetresPer(document.unit);
  json intrinsics = CameraJson(report.camera);
  intrinsics["source"] = report.intrinsics_source;
  if (report.intrinsics_rms_px) intrinsics["rms_px"] = *report.intrinsics_rms_px;
  intrinsics["refined"] = report.intrinsics_sigma.has_value();
  if (report.intrinsics_sigma) {
    intrinsics["sigma"] = {{"order", "fx, fy, cx, cy, k1, k2, p1, p2, k3"},
                           {"values", std::vector<double>(report.intrinsics_sigma->begin(),
                                                          report.intrinsics_sigma->end())}};
  }
  json per_image = json::array();
  const std::vector<std::string> used = UsedStationIds(document);
  for (size_t k = 0; k < used.size() && k < report.image_rms_px.size(); ++k) {
    json image = {{"id", used[k]},
                  {"rms_px", report.image_rms_px[k]},
                  {"outlier", static_cast<bool>(report.image_outlier.at(k))}};
    if (k < report.image_files.size()) image["file"] = report.image_files[k];
    if (k < report.image_points_px.size()) {
      image["points_px"] = JsonPixels(report.image_points_px[k], kPointDecimals);
      image["residuals_px"] = JsonPixels(report.image_residuals_px.at(k), kResidualDecimals);
    }
    per_image.push_back(std::move(image));
  }
  json skipped = json::array();
  for (size_t k = 0; k < document.rejected.size() && k < report.skipped_reasons.size(); ++k) {
    skipped.push_back({{"id", document.station_ids.at(document.rejected[k])},
                       {"reason", report.skipped_reasons[k]}});
  }
  json pose_level = {
      {"method", estimation::Info(report.pose_level.method).name},
      {"X", PoseJson(report.pose_level.X, handeye::XFrameName(document.setup), scale)},
      {"Z", PoseJson(report.pose_level.Z, handeye::ZFrameName(document.setup), scale)}};
  // The pose-level covariance's model check (the joint refinement's covariance is not checked).
  if (report.pose_level.model_check)
    pose_level["model_check"] = ModelCheckJson(*report.pose_level.model_check, scale);
  return {{"intrinsics", intrinsics},
          {"pixel_sigma_px", report.pixel_sigma},
          {"pixel_sigma_estimated", report.pixel_sigma_estimated},
          {"reprojection_rms_px", report.rms_px},
          {"per_image", per_image},
          {"skipped", skipped},
          {"pose_level", pose_level}};
}

json StreamsJson(const StreamReport& report, double scale, json* time_offset) {
  json dropped = {{"outside", report.dropped_outside},
                  {"gap", report.dropped_gap},
                  {"fast", report.dropped_fast},
                  {"thinned", report.thinned}};
  *time_offset = {
      {"seconds", report.offset},
      {"sigma", report.offset_sigma ? json(*report.offset_sigma) : json(nullptr)},
      {"estimated", report.offset_estimated},
      {"convention", "a camera sample stamped t was taken at robot-clock time t + seconds"}};
  if (report.offset_estimated) {
    (*time_offset)["search_window"] = report.search_window;
    (*time_offset)["coarse_seconds"] =
        report.coarse_offset ? json(*report.coarse_offset) : json(nullptr);
    (*time_offset)["coarse_correlation"] = report.coarse_correlation;
    (*time_offset)["profile_evaluations"] = report.profile_evaluations;
    Eigen::Matrix<double, 12, 1> cross = report.covariance_with_XZ;
    cross.segment<3>(3) *= scale;
    cross.segment<3>(9) *= scale;
    (*time_offset)["covariance_with_XZ"] =
        std::vector<double>(cross.data(), cross.data() + cross.size());
  }
  return {{"robot_samples", report.robot_samples},
          {"camera_samples", report.camera_samples},
          {"stations_from", report.camera_gives_stations ? "camera" : "robot"},
          {"interpolation", "local quadratic regression (LOESS, tricube weights)"},
          {"smoothing_seconds", report.smoothing},
          {"smoothed_noise_factor", report.smoothed_noise_factor},
          {"max_gap_seconds", report.max_gap},
          {"max_angular_speed_deg_per_s", report.max_angular_speed * kDegreesPerRadian},
          {"max_linear_speed_per_s", report.max_linear_speed * scale},
          {"max_stations", report.max_stations},
          {"candidates", report.candidates},
          {"dropped", dropped}};
}

// Planar robots (handeye/planar.h): the given component and the family the data cannot tell
// apart.
json FixedJson(const handeye::FixedTranslation& fixed, handeye::Setup setup, double scale) {
  const auto vector = [](const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); };
  return {{"component", handeye::ComponentName(fixed.fix.axis)},
          {"frame", setup == handeye::Setup::kEyeInHand ? "gripper" : "base"},
          {"value", fixed.fix.value * scale},
          {"free_direction_X", vector(fixed.x_direction)},
          {"free_direction_Z", vector(fixed.z_direction)},
          {"family",
           "X with translation t_X + s*free_direction_X and Z with t_Z + s*free_direction_Z fit "
           "the data equally for every s; the given component picks s, and the covariance is "
           "zero along it"}};
}

// The target's scale (estimation/target_scale.h, docs/result-file.md): null when neither
// estimated nor given.
json TargetJson(const ResultDocument& document, const estimation::CalibrationResult& result) {
  const double applied = result.applied_target_scale;
  if (!result.target_scale) {
    if (applied == 1.0) return nullptr;
    return {{"scale", applied}, {"scale_sigma", 0.0}, {"given", true}, {"applied_scale", applied}};
  }
  const estimation::TargetScale& s = *result.target_scale;
  if (!s.observable) return {{"observable", false}, {"reason", s.reason}};
  json target = {{"observable", true},
                 {"scale", s.scale},
                 {"scale_sigma", s.sigma},
                 {"scale_sigma_model", s.model_sigma},
                 {"scale_sigma_jackknife", s.jackknife_sigma},
                 {"jackknife_groups", s.groups},
                 {"mismatch", s.Mismatch()},
                 {"applied_scale", applied}};
  if (document.images && document.images->target_size > 0.0) {
    // The described and the measured size in the file's unit.
    const double unit = 1.0 / io::MetresPer(document.unit);
    const std::string& key = document.images->target_size_key;
    const double described = document.images->target_size * unit;
    target["described"] = {{key, described}};
    target["measured"] = {{key, s.scale * described}, {key + "_sigma", s.sigma * described}};
  }
  return target;
}

// The certificate of global optimality (handeye/certificate.h, docs/certificate.md).
json CertificateJson(const handeye::Certificate& certificate, handeye::Setup setup, double scale) {
  json object = {
      {"certified", certificate.certified},
      {"problem", "chordal least squares of Z = A X B (weights from the noise model)"},
      {"cost", certificate.cost},
      {"lower_bound", certificate.lower_bound},
      {"dual_gap", certificate.gap},
      {"relative_gap", certificate.cost > 0.0 ? certificate.gap / certificate.cost : 0.0},
      {"min_eigenvalue", certificate.min_eigenvalue},
      {"stationarity", certificate.stationarity},
      {"distance_deg", certificate.distance_rotation * kDegreesPerRadian},
      {"distance_translation", certificate.distance_translation * scale}};
  object["polished"] = {{"X", PoseJson(certificate.polished.X, handeye::XFrameName(setup), scale)},
                        {"Z", PoseJson(certificate.polished.Z, handeye::ZFrameName(setup), scale)}};
  return object;
}

json ResultJson(const ResultDocument& document, const estimation::CalibrationResult& result) {
  const double scale = 1.0 / io::MetresPer(document.unit);
  json object = {
      {"hecal_version", hecal::kVersion},
      {"setup", handeye::SetupName(document.setup)},
      {"method", estimation::Info(result.method).name},
      {"units", {{"length", io::UnitName(document.unit)}, {"angle", "rad"}}},
      {"X", PoseJson(result.X, handeye::XFrameName(document.setup), scale)},
      {"Z", PoseJson(result.Z, handeye::ZFrameName(document.setup), scale)},
  };
  if (result.covariance) {
    object["covariance"] =
        CovarianceSectionJson(*result.covariance, document.setup, result.X, result.Z, scale);
    if (result.model_check) {
      object["covariance"]["model_check"] = ModelCheckJson(*result.model_check, scale);
      if (result.model_check->used)
        object["covariance"]["method"] =
            std::string(estimation::CovarianceMethodName(result.covariance->method)) +
            "+model_check";
    }
  }
  const std::vector<std::string> used = UsedStationIds(document);
  json per_station = json::array();
  for (size_t k = 0; k < used.size() && k < result.residuals.size(); ++k) {
    const estimation::StationResidual& r = result.residuals[k];
    per_station.push_back({{"id", used[k]},
                           {"rotation_deg", r.rotation * kDegreesPerRadian},
                           {"translation", r.translation * scale},
                           {"whitened", r.whitened},
                           {"outlier", r.outlier}});
  }
  json rejected = json::array();
  for (int i : document.rejected) rejected.push_back(document.station_ids.at(i));
  json rejected_residuals = json::array();
  for (size_t k = 0; k < result.rejected_residuals.size(); ++k) {
    const estimation::StationResidual& r = result.rejected_residuals[k];
    rejected_residuals.push_back(
        {{"id", k < result.rejected_ids.size() ? result.rejected_ids[k]
                                               : std::to_string(result.rejected[k])},
         {"rotation_deg", r.rotation * kDegreesPerRadian},
         {"translation", r.translation * scale},
         {"whitened", r.whitened}});
  }
  object["residuals"] = {{"rotation_rms_deg", result.rotation_rms * kDegreesPerRadian},
                         {"translation_rms", result.translation_rms * scale},
                         {"per_station", per_station},
                         {"rejected", rejected_residuals}};
  object["noise"] = {{"robot_sigma",
                      {{"rotation_deg", result.robot_sigma.rotation * kDegreesPerRadian},
                       {"translation", result.robot_sigma.translation * scale}}},
                     {"camera_sigma",
                      {{"rotation_deg", result.camera_sigma.rotation * kDegreesPerRadian},
                       {"translation", result.camera_sigma.translation * scale}}},
                     {"estimated", result.sigmas_estimated}};
  if (result.camera_excess.rotation > 0.0 || result.camera_excess.translation > 0.0) {
    object["noise"]["camera_excess"] = {
        {"tilt_deg", result.camera_excess.rotation * kDegreesPerRadian},
        {"depth", result.camera_excess.translation * scale}};
  }
  if (result.student_t_dof > 0.0) object["noise"]["student_t_dof"] = result.student_t_dof;
  object["stations"] = {
      {"used", used}, {"rejected", rejected}, {"outlier_rejection", result.outlier_rejection}};
  if (result.seed) object["seed"] = *result.seed;
  if (result.fixed) object["fixed"] = FixedJson(*result.fixed, document.setup, scale);
  if (json target = TargetJson(document, result); !target.is_null())
    object["target"] = std::move(target);
  if (result.certificate) {
    object["certificate"] = CertificateJson(*result.certificate, document.setup, scale);
    if (result.global_optimum) {
      object["certificate"]["global_optimum"] =
          CertificateJson(*result.global_optimum, document.setup, scale);
    }
  }
  object["warnings"] = result.warnings;
  if (document.images) {
    object["refinement"] = "reprojection";
    object["images"] = ImagesJson(document, *document.images);
  }
  if (document.streams) {
    json time_offset;
    object["streams"] = StreamsJson(*document.streams, scale, &time_offset);
    object["time_offset"] = time_offset;
  }
  return object;
}

// The JSON text with each per-point list ("points_px", "residuals_px": numbers only) on one line
// instead of one number per line: a third of the size (docs/result-file.md).
std::string CompactPixelLists(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  size_t at = 0;
  for (;;) {
    const size_t key =
        std::min(text.find("\"points_px\": [", at), text.find("\"residuals_px\": [", at));
    if (key == std::string::npos) break;
    const size_t open = text.find('[', key);
    if (text[key - 1] == '\\') {  // inside a string: \"points_px\": [
      out.append(text, at, open + 1 - at);
      at = open + 1;
      continue;
    }
    out.append(text, at, open - at);
    int depth = 0;
    size_t k = open;
    for (; k < text.size(); ++k) {
      const char c = text[k];
      if (c == '\n') {
        while (k + 1 < text.size() && text[k + 1] == ' ') ++k;
        continue;
      }
      out += c;
      if (c == ',') out += ' ';
      if (c == '[') ++depth;
      if (c == ']' && --depth == 0) break;
    }
    at = k + 1;
  }
  out.append(text, at, std::string::npos);
  return out;
}

}  // namespace

std::vector<std::string> UsedStationIds(const ResultDocument& document) {
  std::vector<std::string> used;
  for (size_t i = 0; i < document.station_ids.size(); ++i) {
    if (std::find(document.rejected.begin(), document.rejected.end(), static_cast<int>(i)) ==
        document.rejected.end()) {
      used.push_back(document.station_ids[i]);
    }
  }
  return used;
}

ResultFormat ResultFormatForPath(const std::string& path) {
  const auto ends_with = [&](std::string_view suffix) {
    return path.size() >= suffix.size() &&
           path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return ends_with(".yaml") || ends_with(".yml") ? ResultFormat::kYaml : ResultFormat::kJson;
}

std::string FormatResult(const ResultDocument& document, ResultFormat format) {
  json root;
  if (document.all_methods) {
    root = {{"results", json::array()}};
    for (const auto& result : document.results)
      root["results"].push_back(ResultJson(document, result));
    for (const MethodFailure& failure : document.failures) {
      root["results"].push_back({{"hecal_version", hecal::kVersion},
                                 {"setup", handeye::SetupName(document.setup)},
                                 {"method", estimation::Info(failure.method).name},
                                 {"error", failure.message}});
    }
  } else {
    root = ResultJson(document, document.results.at(0));
  }
  if (format == ResultFormat::kJson) return CompactPixelLists(root.dump(2)) + "\n";
  return YamlText(root);
}

void WriteResult(const std::string& path, const ResultDocument& document) {
  io::WriteFileAtomically(path, FormatResult(document, ResultFormatForPath(path)));
}

}  // namespace hecal::report
