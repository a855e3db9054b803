// The calibration result as readable text: see result_text.h.
#include "hecal/report/result_text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/estimation/methods.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/rotation.h"
#include "hecal/io/units.h"
#include "hecal/report/translation_sigma.h"

namespace hecal::report {
namespace {
// The printout lists every station up to this many, else the largest residuals only.
constexpr size_t kMaxPrintedStations = 200;
constexpr size_t kLargestPrintedStations = 20;

void PrintPose(std::ostream& out, std::string_view name, std::string_view frame, const Pose& T,
               double scale, std::string_view unit) {
  const AxisAngle aa = AxisAngleFromMatrix(T.linear());
  out << name << " = " << frame << "\n";
  for (int r = 0; r < 3; ++r) {
    out << "  [";
    for (int c = 0; c < 3; ++c) out << std::setw(11) << T.linear()(r, c);
    out << " |" << std::setw(11) << T.translation()(r) * scale << " ]\n";
  }
  out << "  rotation " << aa.angle * kDegreesPerRadian << " deg about (" << aa.axis.transpose()
      << "), translation " << (T.translation() * scale).transpose() << " " << unit << "\n";
}

// 1σ per axis in degrees and millimetres, whatever the file unit (the result file has both),
// along the pose's own axes (the covariance's; translation_sigma.h gives t's parent-frame σ).
void PrintSigma(std::ostream& out, std::string_view name, const Matrix6d& covariance) {
  const Vector6d sd = covariance.diagonal().cwiseSqrt();
  out << "  1σ " << name << ": rotation (" << sd.head<3>().transpose() * kDegreesPerRadian
      << ") deg, translation (" << sd.tail<3>().transpose() * 1000.0 << ") mm\n";
}

// The target's scale (estimation/target_scale.h): measured, given, or why not observable.
void PrintTargetScale(std::ostream& out, const estimation::CalibrationResult& result) {
  const double applied = result.applied_target_scale;
  if (!result.target_scale) {
    if (applied != 1.0) out << "target scale: " << applied << " (given; not estimated)\n";
    return;
  }
  const estimation::TargetScale& s = *result.target_scale;
  if (!s.observable) {
    out << "target scale: not observable (" << s.reason << ")\n";
    return;
  }
  out << "target scale (measured ÷ described size): " << s.scale << " ± " << s.sigma << " (1σ); "
      << (applied != 1.0 ? "X and Z at the measured size" : "X and Z at the described size")
      << "\n";
}

// The certificate of global optimality (handeye/certificate.h).
void PrintCertificate(std::ostream& out, const estimation::CalibrationResult& result, double scale,
                      std::string_view unit) {
  if (!result.certificate) return;
  const handeye::Certificate& c = *result.certificate;
  out << "certificate: " << (c.certified ? "globally optimal" : "NOT certified")
      << " (chordal least squares polished " << c.distance_rotation * kDegreesPerRadian << " deg / "
      << c.distance_translation * scale << " " << unit << " from X; dual gap " << std::scientific
      << std::setprecision(2) << c.gap << ", smallest dual eigenvalue " << c.min_eigenvalue
      << std::fixed << std::setprecision(6) << ")\n";
  if (result.global_optimum) {
    const Pose& X = result.global_optimum->polished.X;
    out << "  certified global optimum from a closed-form start: X translation "
        << X.translation().transpose() * scale << " " << unit << "\n";
  }
}

}  // namespace

void PrintResultSummary(std::ostream& out, const ResultDocument& document,
                        const estimation::CalibrationResult& result) {
  const double scale = 1.0 / io::MetresPer(document.unit);
  const std::string_view unit = io::UnitName(document.unit);
  out << std::fixed << std::setprecision(6);
  out << "method " << estimation::Info(result.method).name << " ("
      << handeye::SetupName(document.setup) << ", " << result.residuals.size() << " stations)\n";
  PrintPose(out, "X", handeye::XFrameName(document.setup), result.X, scale, unit);
  PrintPose(out, "Z", handeye::ZFrameName(document.setup), result.Z, scale, unit);
  if (result.fixed) {
    const Eigen::Vector3d& d = result.fixed->x_direction;
    out << "fixed: " << handeye::ComponentName(result.fixed->fix.axis)
        << " of X = " << result.fixed->fix.value * scale << " " << unit
        << " (given, not estimated: the robot "
        << "rotates about one axis, so X's translation along (" << d.x() << ", " << d.y() << ", "
        << d.z() << ") of the "
        << (document.setup == handeye::Setup::kEyeInHand ? "gripper" : "base")
        << " frame is not observed; Z's translation moves with it)\n";
  }
  PrintTargetScale(out, result);
  PrintCertificate(out, result, scale, unit);
  if (result.covariance) {
    const estimation::CalibrationCovariance& c = *result.covariance;
    out << "covariance: " << estimation::CovarianceMethodName(c.method);
    if (c.method == estimation::CovarianceMethod::kMonteCarlo) {
      out << " (" << c.samples << " samples)";
    } else if (c.solves > 0) {
      out << " (" << c.solves << " solves)";
    }
    out << "\n";
    PrintSigma(out, "X", c.X());
    PrintTranslationSigmaInParent(out, "X", handeye::XFrameName(document.setup), result.X, c.X());
    PrintSigma(out, "Z", c.Z());
    PrintTranslationSigmaInParent(out, "Z", handeye::ZFrameName(document.setup), result.Z, c.Z());
  }
  out << std::setprecision(4) << "residual RMS: " << result.rotation_rms * kDegreesPerRadian
      << " deg, " << result.translation_rms * scale << " " << unit << "\n";
  out << "  station        rotation_deg   translation_" << unit << "   whitened\n";
  const std::vector<std::string> used = UsedStationIds(document);
  const size_t shown = std::min(used.size(), result.residuals.size());
  // Every station up to kMaxPrintedStations; above, the largest whitened residuals (the file
  // has them all).
  std::vector<size_t> order(shown);
  std::iota(order.begin(), order.end(), size_t{0});
  if (shown > kMaxPrintedStations) {
    std::partial_sort(order.begin(), order.begin() + kLargestPrintedStations, order.end(),
                      [&](size_t a, size_t b) {
                        return result.residuals[a].whitened > result.residuals[b].whitened;
                      });
    order.resize(kLargestPrintedStations);
    out << "  (the " << kLargestPrintedStations << " largest of " << shown
        << " stations; every station is in the result file)\n";
  }
  for (const size_t k : order) {
    const estimation::StationResidual& r = result.residuals[k];
    out << "  " << std::left << std::setw(14) << used[k] << std::right << std::setw(12)
        << r.rotation * kDegreesPerRadian << std::setw(17) << r.translation * scale << std::setw(11)
        << r.whitened << (r.outlier ? "   > 3σ, check this station" : "") << "\n";
  }
  for (size_t k = 0; k < result.rejected_residuals.size(); ++k) {
    const estimation::StationResidual& r = result.rejected_residuals[k];
    const std::string id = k < result.rejected_ids.size() ? result.rejected_ids[k]
                                                          : std::to_string(result.rejected[k] + 1);
    out << "  " << std::left << std::setw(14) << id << std::right << std::setw(12)
        << r.rotation * kDegreesPerRadian << std::setw(17) << r.translation * scale << std::setw(11)
        << r.whitened << "   rejected: outlier, not used\n";
  }
  for (const std::string& warning : result.warnings) out << "warning: " << warning << "\n";
  out.unsetf(std::ios::floatfield);
}

// `--method all`: one line per method, side by side, with the difference from ml and the
// predicted RMS error of X (sqrt of the trace of its rotation and translation covariance).
void PrintMethodComparison(std::ostream& out, const ResultDocument& document) {
  const double scale = 1.0 / io::MetresPer(document.unit);
  const std::string_view unit = io::UnitName(document.unit);
  const auto ml = std::find_if(document.results.begin(), document.results.end(),
                               [](const auto& r) { return r.method == estimation::Method::kMl; });
  const std::string length = "res_" + std::string(unit);
  out << "\nside by side (X " << handeye::XFrameName(document.setup) << ")\n  " << std::left
      << std::setw(16) << "method" << std::right << std::setw(11) << "tx" << std::setw(12) << "ty"
      << std::setw(12) << "tz" << std::setw(12) << "res_deg" << std::setw(9) << length;
  if (ml != document.results.end())
    out << std::setw(12) << "vs_ml_deg" << std::setw(10) << "vs_ml_" + std::string(unit);
  out << std::setw(11) << "1σ_deg" << std::setw(10) << "1σ_mm"
      << "  covariance\n";
  out << std::fixed;
  for (const estimation::CalibrationResult& r : document.results) {
    const Eigen::Vector3d t = r.X.translation() * scale;
    out << "  " << std::left << std::setw(16) << estimation::Info(r.method).name << std::right
        << std::setprecision(6) << std::setw(11) << t.x() << std::setw(12) << t.y() << std::setw(12)
        << t.z() << std::setprecision(4) << std::setw(12) << r.rotation_rms * kDegreesPerRadian
        << std::setw(9) << r.translation_rms * scale;
    if (ml != document.results.end()) {
      const Pose d = ml->X.inverse() * r.X;
      out << std::setw(12) << AxisAngleFromMatrix(d.linear()).angle * kDegreesPerRadian
          << std::setw(10) << (r.X.translation() - ml->X.translation()).norm() * scale;
    }
    if (r.covariance) {  // predicted RMS error of X: sqrt(trace) of each block
      const Matrix6d C = r.covariance->X();
      out << std::setw(10) << std::sqrt(C.topLeftCorner<3, 3>().trace()) * kDegreesPerRadian
          << std::setw(9) << std::sqrt(C.bottomRightCorner<3, 3>().trace()) * 1000.0 << "  "
          << estimation::CovarianceMethodName(r.covariance->method);
    }
    out << "\n";
  }
  for (const MethodFailure& failure : document.failures)
    out << "  " << std::left << std::setw(16) << estimation::Info(failure.method).name << std::right
        << "refused: " << failure.message << "\n";
  out.unsetf(std::ios::floatfield);
}

namespace {

void PrintRefinedIntrinsics(std::ostream& out, const pose::CameraModel& before,
                            const ImageReport& report) {
  constexpr std::array<const char*, pose::kNumIntrinsics> kNames = {"fx", "fy", "cx", "cy", "k1",
                                                                    "k2", "p1", "p2", "k3"};
  const pose::IntrinsicParameters start = pose::IntrinsicsOf(before);
  const pose::IntrinsicParameters refined = pose::IntrinsicsOf(report.camera);
  out << "intrinsics refined with X and Z (before → after ± 1σ):\n";
  for (int k = 0; k < pose::kNumIntrinsics; ++k) {
    out << "  " << kNames[static_cast<size_t>(k)] << " " << std::setprecision(k < 4 ? 7 : 5)
        << start(k) << " → " << refined(k) << " ± " << std::setprecision(2)
        << (*report.intrinsics_sigma)[static_cast<size_t>(k)] << "\n";
  }
  out << std::setprecision(6);
}

void PrintImageTable(std::ostream& out, const ResultDocument& document, const ImageReport& report) {
  out << std::fixed << std::setprecision(3) << "reprojection: RMS " << report.rms_px
      << " px over every point; pixel sigma " << report.pixel_sigma << " px ("
      << (report.pixel_sigma_estimated ? "estimated" : "given") << ")\n  image          rms_px\n";
  const std::vector<std::string> used = UsedStationIds(document);
  for (size_t k = 0; k < used.size(); ++k) {
    out << "  " << std::left << std::setw(14) << used[k] << std::right << std::setw(7)
        << report.image_rms_px[k] << (report.image_outlier[k] ? "   > 3σ, check this image" : "")
        << "\n";
  }
  out.unsetf(std::ios::floatfield);
}

}  // namespace

void PrintImageResultSummary(std::ostream& out, const ResultDocument& document,
                             const pose::CameraModel& camera_before) {
  const estimation::CalibrationResult& result = document.results.front();
  const ImageReport& report = *document.images;
  const Pose step = report.pose_level.X.inverse() * result.X;
  const double scale = 1.0 / io::MetresPer(document.unit);
  out << "\npose level (" << estimation::Info(report.pose_level.method).name
      << " on the PnP poses), then the joint reprojection refinement moved X by "
      << std::setprecision(4) << AxisAngleFromMatrix(step.linear()).angle * 180.0 / std::numbers::pi
      << " deg, " << (result.X.translation() - report.pose_level.X.translation()).norm() * scale
      << " " << io::UnitName(document.unit) << "\n";
  out.unsetf(std::ios::floatfield);
  PrintResultSummary(out, document, result);
  if (report.intrinsics_sigma) PrintRefinedIntrinsics(out, camera_before, report);
  PrintImageTable(out, document, report);
}

void PrintStreamSummary(std::ostream& out, const ResultDocument& document) {
  if (!document.streams) return;
  const StreamReport& s = *document.streams;
  const int used = static_cast<int>(document.station_ids.size() - document.rejected.size());
  out << "\nstreams: robot " << s.robot_samples << " samples, camera " << s.camera_samples
      << "; stations from the " << (s.camera_gives_stations ? "camera" : "robot")
      << " stream: " << used << " used of " << s.candidates
      << " samples (dropped: " << s.dropped_outside << " outside the other stream, "
      << s.dropped_gap << " at gaps over " << std::setprecision(3) << s.max_gap << " s, "
      << s.dropped_fast << " in fast motion, " << s.thinned << " thinned; "
      << document.rejected.size() << " rejected as outliers)\n";
  out << "time offset (camera stamp t = robot time t + offset): " << std::fixed
      << std::setprecision(2) << s.offset * 1e3 << " ms";
  if (s.offset_sigma) out << " ± " << *s.offset_sigma * 1e3 << " ms (1σ)";
  if (s.offset_estimated) {
    out << ", fitted with X and Z from the angular-speed correlation's "
        << (s.coarse_offset ? *s.coarse_offset * 1e3 : 0.0) << " ms (r = " << std::setprecision(3)
        << s.coarse_correlation << ")";
  } else {
    out << (s.coarse_offset ? "" : " (given or unobservable)");
  }
  out << "\n";
  out.unsetf(std::ios::floatfield);
}

}  // namespace hecal::report
