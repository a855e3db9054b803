// Strict reading of a result file for the HTML report: report_input.h, docs/report.md,
// docs/result-file.md (the fields and their types).
#include "hecal/report/report_input.h"

#include <cmath>
#include <initializer_list>

#include "hecal/core/error.h"

namespace hecal::report {
namespace {

using nlohmann::json;

constexpr const char* kFix =
    "give a result file written by `hecal calibrate --output FILE.json` (docs/result-file.md)";

// Checks fields below one object; `path` is the JSON path shown in errors ("results[0].X").
class Checker {
 public:
  Checker(const std::string& source, const json& value, std::string path)
      : source_(source), value_(value), path_(std::move(path)) {}

  [[noreturn]] void Fail(const std::string& field, const std::string& expected) const {
    throw InputError(source_, 0, "field " + Join(field) + ": expected " + expected, kFix);
  }

  const json& Get(const std::string& field) const {
    if (!value_.is_object()) Fail("", "an object");
    const auto it = value_.find(field);
    if (it == value_.end())
      throw InputError(source_, 0, "field " + Join(field) + " is missing", kFix);
    return *it;
  }
  bool Has(const std::string& field) const { return value_.contains(field); }

  Checker Object(const std::string& field) const {
    const json& v = Get(field);
    if (!v.is_object()) Fail(field, "an object");
    return {source_, v, Join(field)};
  }
  void String(const std::string& field) const {
    if (!Get(field).is_string()) Fail(field, "a string");
  }
  void OneOf(const std::string& field, std::initializer_list<const char*> choices) const {
    const json& v = Get(field);
    std::string names;
    for (const char* choice : choices) {
      if (v.is_string() && v.get<std::string>() == choice) return;
      names += names.empty() ? "" : " or ";
      names += choice;
    }
    Fail(field, names);
  }
  void Bool(const std::string& field) const {
    if (!Get(field).is_boolean()) Fail(field, "true or false");
  }
  void Number(const std::string& field) const {
    const json& v = Get(field);
    if (!v.is_number() || !std::isfinite(v.get<double>())) Fail(field, "a finite number");
  }
  void Vector(const std::string& field, size_t n) const {
    if (!IsVector(Get(field), n)) Fail(field, std::to_string(n) + " finite numbers");
  }
  void Matrix(const std::string& field, size_t n) const {
    const json& v = Get(field);
    bool ok = v.is_array() && v.size() == n;
    for (size_t r = 0; ok && r < n; ++r) ok = IsVector(v[r], n);
    if (!ok) Fail(field, "a " + std::to_string(n) + "x" + std::to_string(n) + " matrix of numbers");
  }
  // An array whose every element is checked by `each` (a Checker on the element).
  template <typename Each>
  void Array(const std::string& field, Each each) const {
    const json& v = Get(field);
    if (!v.is_array()) Fail(field, "an array");
    for (size_t k = 0; k < v.size(); ++k)
      each(Checker(source_, v[k], Join(field) + "[" + std::to_string(k) + "]"));
  }
  // An array of [u, v] pairs of finite numbers (pixels); returns its length.
  size_t Pairs(const std::string& field) const {
    const json& v = Get(field);
    if (!v.is_array()) Fail(field, "an array of [u, v] pairs of numbers");
    for (size_t k = 0; k < v.size(); ++k)
      if (!IsVector(v[k], 2))
        Fail(field + "[" + std::to_string(k) + "]", "[u, v]: 2 finite numbers");
    return v.size();
  }
  void Strings(const std::string& field) const {
    Array(field, [](const Checker& c) {
      if (!c.value_.is_string()) c.Fail("", "a string");
    });
  }

 private:
  static bool IsVector(const json& v, size_t n) {
    if (!v.is_array() || v.size() != n) return false;
    for (const json& x : v)
      if (!x.is_number() || !std::isfinite(x.get<double>())) return false;
    return true;
  }
  std::string Join(const std::string& field) const {
    if (field.empty()) return path_.empty() ? "(top level)" : path_;
    return path_.empty() ? field : path_ + "." + field;
  }

  const std::string& source_;
  const json& value_;
  std::string path_;
};

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
}

}  // namespace

json ParseResultForReport(std::string_view text, const std::string& source) {
  json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) {
    throw InputError(source, 0,
                     "not JSON (hecal report reads the JSON result file; YAML is not read)", kFix);
  }
  if (!document.is_object()) Checker(source, document, "").Fail("", "a JSON object");
  if (document.contains("certificate")) {
    throw InputError(source, 0,
                     "a target-free result (`--method global`): hecal report does not show it yet",
                     "see the result with `hecal calibrate --method global` (docs/global.md)");
  }
  json out = {{"all_methods", document.contains("results")}, {"results", json::array()}};
  if (document.contains("results")) {
    const Checker top(source, document, "");
    top.Array("results", CheckResult);
    if (document["results"].empty()) top.Fail("results", "at least one result");
    out["results"] = document["results"];
  } else {
    CheckResult(Checker(source, document, ""));
    out["results"].push_back(std::move(document));
  }
  return out;
}

}  // namespace hecal::report
