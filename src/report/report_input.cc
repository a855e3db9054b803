// Strict reading of a result file for the HTML report: report_input.h, docs/report.md,
// docs/result-file.md (the fields and their types).
#include "hecal/report/report_input.h"

#include <cmath>
#include <initializer_list>

#include "hecal/core/error.h"
#include "hecal/report/json_checker.h"

namespace hecal::report {
namespace {

using nlohmann::json;
using Checker = JsonChecker;

// The fix of every error about a target-free result file.
constexpr const char* kGlobalFix =
    "give a result file written by `hecal calibrate --method global --output FILE.json` "
    "(docs/result-file.md#target-free---method-global)";

// The fix of every error about a calibration result file.
constexpr const char* kFix =
    "give a result file written by `hecal calibrate --output FILE.json` (docs/result-file.md)";

void CheckPose(const Checker& pose) {
  pose.String("frame");
  pose.Matrix("matrix", 4);
  pose.Vector("translation", 3);
  pose.Vector("quaternion_wxyz", 4);
}

void CheckSigma(const Checker& sigma) {
  sigma.Vector("rotation_deg", 3);
  sigma.Vector("translation", 3);
}

void CheckCovariance(const Checker& c) {
  c.Matrix("X", 6);
  c.Matrix("Z", 6);
  c.String("method");
  const Checker sigma = c.Object("sigma");
  for (const char* pose : {"X", "Z"}) {
    const Checker s = sigma.Object(pose);
    CheckSigma(s);
    const Checker parent = s.Object("translation_in_parent");
    parent.String("frame");
    parent.Vector("translation", 3);
  }
  if (!c.Has("model_check")) return;
  const Checker check = c.Object("model_check");
  check.Bool("possible");
  if (!check.Get("possible").get<bool>()) return check.String("reason");
  for (const char* part : {"sigma_model", "sigma_check"}) {
    const Checker s = check.Object(part);
    CheckSigma(s.Object("X"));
    CheckSigma(s.Object("Z"));
  }
  check.Strings("flagged");
  check.Bool("used");
}

void CheckImages(const Checker& images) {
  const Checker intrinsics = images.Object("intrinsics");
  for (const char* field : {"fx", "fy", "cx", "cy", "width", "height"}) intrinsics.Number(field);
  intrinsics.String("source");
  images.Number("reprojection_rms_px");
  images.Number("pixel_sigma_px");
  images.Array("per_image", [](const Checker& c) {
    c.String("id");
    c.Number("rms_px");
    c.Bool("outlier");
    if (c.Has("file")) c.String("file");
    // The per-point fields (this version on): both or neither, one residual per point.
    if (c.Has("points_px") || c.Has("residuals_px")) {
      if (c.Pairs("residuals_px") != c.Pairs("points_px"))
        c.Fail("residuals_px", "one [du, dv] per point of points_px");
    }
  });
  images.Array("skipped", [](const Checker& c) {
    c.String("id");
    c.String("reason");
  });
}

void CheckResult(const Checker& r) {
  r.String("hecal_version");
  r.OneOf("setup", {"eye-in-hand", "eye-to-hand"});
  r.String("method");
  if (r.Has("error")) return r.String("error");  // a method of `all` that refused the data
  r.Object("units").OneOf("length", {"m", "mm"});
  CheckPose(r.Object("X"));
  CheckPose(r.Object("Z"));
  if (r.Has("covariance")) CheckCovariance(r.Object("covariance"));
  const Checker residuals = r.Object("residuals");
  residuals.Number("rotation_rms_deg");
  residuals.Number("translation_rms");
  const auto station = [](const Checker& c) {
    c.String("id");
    c.Number("rotation_deg");
    c.Number("translation");
    c.Number("whitened");
  };
  residuals.Array("per_station", [&](const Checker& c) {
    station(c);
    c.Bool("outlier");
  });
  residuals.Array("rejected", station);
  const Checker noise = r.Object("noise");
  for (const char* side : {"robot_sigma", "camera_sigma"}) {
    const Checker s = noise.Object(side);
    s.Number("rotation_deg");
    s.Number("translation");
  }
  noise.Bool("estimated");
  const Checker stations = r.Object("stations");
  stations.Strings("used");
  stations.Strings("rejected");
  r.Strings("warnings");
  if (r.Has("images")) CheckImages(r.Object("images"));
  if (r.Has("target")) {  // docs/target-scale.md
    const Checker target = r.Object("target");
    if (target.Has("scale")) {
      target.Number("scale");
      target.Number("scale_sigma");
      target.Number("applied_scale");
    } else {
      target.String("reason");
    }
  }
  if (r.Has("certificate")) {  // docs/certificate.md
    const Checker certificate = r.Object("certificate");
    certificate.Bool("certified");
    certificate.Number("dual_gap");
  }
}

}  // namespace

json ParseResultForReport(std::string_view text, const std::string& source) {
  json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) {
    throw InputError(source, 0,
                     "not JSON (hecal report reads the JSON result file; YAML is not read)", kFix);
  }
  if (!document.is_object()) Checker(source, document, "", kFix).Fail("", "a JSON object");
  if (IsGlobalResult(document)) {
    throw InputError(source, 0,
                     "a target-free result (`--method global`), not a calibration result",
                     "read it with ParseGlobalResultForReport (docs/report.md)");
  }
  json out = {{"all_methods", document.contains("results")}, {"results", json::array()}};
  if (document.contains("results")) {
    const Checker top(source, document, "", kFix);
    top.Array("results", CheckResult);
    if (document["results"].empty()) top.Fail("results", "at least one result");
    out["results"] = document["results"];
  } else {
    CheckResult(Checker(source, document, "", kFix));
    out["results"].push_back(std::move(document));
  }
  return out;
}

bool IsGlobalResult(const json& document) {
  // Every pose-based result carries a `certificate` too (handeye/certificate.h); the target-free
  // one is the one whose method is `global`.
  return document.is_object() && document.contains("certificate") &&
         document.value("method", std::string()) == "global";
}

json ParseGlobalResultForReport(std::string_view text, const std::string& source) {
  json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) throw InputError(source, 0, "not JSON", kGlobalFix);
  const Checker r(source, document, "", kGlobalFix);
  if (!document.is_object()) r.Fail("", "a JSON object");
  r.OneOf("method", {"global"});
  r.OneOf("setup", {"eye-in-hand", "eye-to-hand"});
  const Checker x = r.Object("X");
  x.String("frame");
  x.Matrix("rotation", 3);
  x.Vector("translation_m", 3);
  const Checker c = r.Object("certificate");
  for (const char* field : {"lower", "upper", "cubes", "lps", "seconds", "time_budget_s",
                            "max_cubes", "search_seconds", "epsilon", "relative_gap", "reach_m"}) {
    c.Number(field);
  }
  c.Bool("certified");
  c.String("stopped_by");
  c.String("error");
  const Checker l = r.Object("l_infinity_X");
  l.Matrix("rotation", 3);
  l.Vector("translation_m", 3);
  const Checker cov = r.Object("covariance");
  cov.String("method");
  cov.Matrix("X", 6);
  cov.Matrix("independent_pairs_X", 6);
  cov.String("convention");
  for (const char* field :
       {"ray_sigma_rad", "robot_rotation_sigma_rad", "robot_translation_sigma_m"})
    cov.Number(field);
  cov.OneOf("robot_sigma", {"given", "estimated"});
  const Checker parent = cov.Object("translation_in_parent");
  parent.String("frame");
  parent.Vector("translation", 3);
  const Checker check = cov.Object("model_check");
  check.Bool("possible");
  if (check.Get("possible").get<bool>()) {
    for (const char* part : {"sigma_model", "sigma_check"}) {
      const Checker sigma = check.Object(part).Object("X");
      sigma.Vector("rotation_rad", 3);
      sigma.Vector("translation_m", 3);
    }
    check.Strings("flagged");
    check.Bool("used");
  } else {
    check.String("reason");
  }
  const Checker polish = r.Object("polish");
  polish.Number("rms_rad");
  polish.Number("pairs");
  const Checker matches = r.Object("matches");
  for (const char* field :
       {"inliers", "threshold_rad", "pixel_threshold_rad", "error_scale_rad", "pixel_sigma"}) {
    matches.Number(field);
  }
  matches.Array("removed", [](const Checker& m) {
    m.String("first");
    m.String("second");
    m.Number("id");
    m.String("by");
  });
  if (r.Has("motions")) {  // older files have no per-motion residuals
    r.Array("motions", [](const Checker& m) {
      m.String("first");
      m.String("second");
      for (const char* field : {"pairs", "removed", "rms_rad", "max_rad"}) m.Number(field);
    });
  }
  r.Strings("warnings");
  return document;
}

}  // namespace hecal::report
