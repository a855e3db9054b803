#include "hecal/report/pivot_file.h"

#include <nlohmann/json.hpp>

#include "hecal/geometry/angle_units.h"
#include "hecal/io/atomic_file.h"
#include "hecal/report/json_matrix.h"
#include "hecal/report/yaml_tree.h"
#include "hecal/version.h"

namespace hecal::report {
namespace {

using nlohmann::json;

json PointJson(const std::string& frame, const Eigen::Vector3d& point,
               const Eigen::Matrix3d& covariance, double scale) {
  return {{"frame", frame},
          {"translation", JsonVector(scale * point)},
          {"sigma", JsonVector(scale * covariance.diagonal().cwiseSqrt())}};
}

json PivotJson(const PivotDocument& document) {
  const estimation::PivotResult& r = document.result;
  const double scale = 1.0 / io::MetresPer(document.unit);
  json stations = json::array();
  json used = json::array(), rejected = json::array();
  for (size_t i = 0; i < r.stations.size(); ++i) {
    const estimation::PivotStation& s = r.stations[i];
    const std::string& id = document.station_ids.at(i);
    stations.push_back({{"id", id},
                        {"residual", JsonVector(scale * s.residual)},
                        {"distance", scale * s.residual.norm()},
                        {"standardized", s.standardized},
                        {"outlier", s.outlier},
                        {"used", s.used}});
    (s.used ? used : rejected).push_back(id);
  }
  return {
      {"hecal_version", hecal::kVersion},
      {"kind", "pivot"},
      {"units", {{"length", io::UnitName(document.unit)}, {"angle", "rad"}}},
      {"tip", PointJson("flange", r.tip, r.covariance.topLeftCorner<3, 3>(), scale)},
      {"pivot", PointJson("base", r.pivot, r.covariance.bottomRightCorner<3, 3>(), scale)},
      {"covariance",
       {{"matrix", JsonRows(scale * scale * r.covariance)},
        {"order", "tip x y z (flange), pivot x y z (base)"}}},
      {"algebraic",
       {{"tip", JsonVector(scale * r.algebraic_tip)},
        {"pivot", JsonVector(scale * r.algebraic_pivot)}}},
      {"noise",
       {{"robot_sigma",
         {{"rotation_deg", kDegreesPerRadian * r.sigma.rotation},
          {"translation", scale * r.sigma.translation}}},
        {"estimated", r.sigma_estimated},
        {"chi_square", r.chi_square},
        {"dof", r.dof}}},
      {"residuals",
       {{"rms", scale * r.rms},
        {"outlier_chi_square", estimation::kPivotOutlierChiSquare},
        {"per_station", stations}}},
      {"stations",
       {{"used", used}, {"rejected", rejected}, {"outlier_rejection", document.outlier_rejection}}},
      {"min_tilt_deg", kDegreesPerRadian * r.min_tilt},
      {"iterations", r.iterations},
      {"warnings", r.warnings}};
}

}  // namespace

std::string FormatPivotResult(const PivotDocument& document, ResultFormat format) {
  const json root = PivotJson(document);
  return format == ResultFormat::kJson ? root.dump(2) + "\n" : YamlText(root);
}

void WritePivotResult(const std::string& path, const PivotDocument& document) {
  io::WriteFileAtomically(path, FormatPivotResult(document, ResultFormatForPath(path)));
}

}  // namespace hecal::report
