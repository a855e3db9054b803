// hecal.calibrate (docs/python.md#hecalcalibrate) and its result, hecal.CalibrationResult.
//
// From arrays: robot = T_base_gripper and camera = T_camera_target as N×4×4 arrays, one per
// station → jobs::CalibratePoses (poses in memory; units robot_unit / camera_unit, or unit/units
// for both). From files: robot and camera as paths of any pose table hecal reads → jobs::
// CalibrateFromPoseFiles with the read options of the CLI's flags (units, degrees, euler,
// robot_inverse, camera_inverse). The keywords mirror `hecal calibrate`'s flags (--robot-sigma →
// robot_sigma, --keep-outliers → keep_outliers, ...). The GIL is released while the job runs.
//
// The result wraps the job's report::ResultDocument: to_json() is report::FormatResult(document,
// kJson) — the bytes `hecal calibrate --output out.json` writes for the same files and options —
// and to_dict() is json.loads of it. The attributes are the document's, lengths in its unit (the
// robot list's / file's), angles in radians; covariance 12×12 of right perturbations
// (rx, ry, rz, tx, ty, tz) of X then Z.
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "bindings.h"

namespace hecal::python {

// The convention check's words in the module's terms (keyword arguments).
handeye::ConventionWords PythonWords() {
  handeye::ConventionWords words;
  words.setup = "setup";  // "run with setup eye-to-hand"
  words.units = "units";
  words.invert_robot = "pass robot_inverse=True";
  words.keep_robot = "leave out robot_inverse=True";
  words.invert_camera = "pass camera_inverse=True";
  words.keep_camera = "leave out camera_inverse=True";
  words.import_matrix_lines = "hecal import --format matrix16";
  return words;
}

std::optional<handeye::Setup> ParseSetupArgument(const std::optional<std::string>& setup) {
  if (!setup || *setup == "auto") return std::nullopt;
  const auto parsed = handeye::ParseSetup(*setup);
  if (!parsed) {
    ThrowArgument("setup", "unknown setup '" + *setup + "'",
                  "use 'eye-in-hand' (camera on the robot), 'eye-to-hand' (camera fixed) or "
                  "'auto' / None (the setup the data fit)");
  }
  return parsed;
}

std::optional<io::LengthUnit> ParseUnitArgument(const std::string& argument,
                                                const std::optional<std::string>& text) {
  if (!text) return std::nullopt;
  const auto unit = io::ParseLengthUnit(*text);
  if (!unit) ThrowArgument(argument, "unknown length unit '" + *text + "'", "use 'm' or 'mm'");
  return unit;
}

// --robot-sigma MM,DEG: "MM,DEG" or (mm, deg) → metres and radians.
std::optional<estimation::PoseSigma> ParseSigmaArgument(const std::string& argument,
                                                        const py::handle& value) {
  if (value.is_none()) return std::nullopt;
  double mm = 0.0, deg = 0.0;
  bool ok = false;
  if (py::isinstance<py::str>(value)) {
    const std::string text = value.cast<std::string>();
    const size_t comma = text.find(',');
    if (comma != std::string::npos) {
      try {
        size_t used_mm = 0, used_deg = 0;
        const std::string a = text.substr(0, comma), b = text.substr(comma + 1);
        mm = std::stod(a, &used_mm);
        deg = std::stod(b, &used_deg);
        ok = used_mm == a.size() && used_deg == b.size();
      } catch (const std::exception&) {
      }
    }
  } else if (py::isinstance<py::sequence>(value) && py::len(value) == 2) {
    try {
      const auto pair = value.cast<std::pair<double, double>>();
      mm = pair.first;
      deg = pair.second;
      ok = true;
    } catch (const py::cast_error&) {
    }
  }
  if (!ok || !std::isfinite(mm) || !std::isfinite(deg)) {
    ThrowArgument(argument, "expected the noise per axis as \"MM,DEG\" or (mm, deg)",
                  "write e.g. " + argument + "=(0.5, 0.05): 0.5 mm and 0.05° per axis");
  }
  return estimation::PoseSigma{deg / kDegreesPerRadian, mm * 1e-3};
}

std::optional<EulerSequence> ParseEulerArgument(const std::optional<std::string>& euler) {
  if (!euler) return std::nullopt;
  auto sequence = EulerSequence::Parse(*euler);
  if (!sequence) {
    ThrowArgument("euler", "unknown Euler sequence '" + *euler + "'",
                  "three letters of x, y, z: lowercase extrinsic (e.g. 'xyz'), uppercase "
                  "intrinsic (e.g. 'ZYX')");
  }
  return sequence;
}

estimation::CalibrateOptions CalibrateOptionsFromArguments(
    const std::string& method, py::handle robot_sigma, py::handle camera_sigma,
    bool keep_outliers, const std::string& robust, const std::optional<std::string>& covariance,
    int covariance_samples, std::uint64_t seed, int threads) {
  estimation::CalibrateOptions options;
  if (method != "all") {
    const auto parsed = estimation::ParseMethod(method);
    if (!parsed) {
      std::string names;
      for (const auto& info : estimation::AllMethods()) names += std::string(info.name) + " ";
      ThrowArgument("method", "unknown method '" + method + "'", "use one of: " + names + "all");
    }
    options.method = *parsed;
  }
  options.robot_sigma = ParseSigmaArgument("robot_sigma", robot_sigma);
  options.camera_sigma = ParseSigmaArgument("camera_sigma", camera_sigma);
  const auto loss = estimation::ParseRobustLoss(robust);
  if (!loss) ThrowArgument("robust", "unknown loss '" + robust + "'", "use none, huber or cauchy");
  options.robust_loss = *loss;
  if (covariance) {
    const auto parsed = estimation::ParseCovarianceMethod(*covariance);
    if (!parsed || *parsed == estimation::CovarianceMethod::kNone) {
      ThrowArgument("covariance", "unknown covariance method '" + *covariance + "'",
                    "use linear, unscented, montecarlo or information (or None for the "
                    "method's default)");
    }
    options.covariance.method = parsed;
  }
  options.covariance.samples = covariance_samples;
  options.covariance.seed = seed;
  options.consensus.seed = seed;
  options.covariance.threads = threads;
  options.reject_outliers = !keep_outliers;
  return options;
}

namespace {

// One method's result within a document (the document shared by every result of a run).
struct Result {
  std::shared_ptr<const report::ResultDocument> document;
  size_t index = 0;

  const estimation::CalibrationResult& result() const { return document->results[index]; }
  double PerMetre() const { return 1.0 / io::MetresPer(document->unit); }
  py::array_t<double> PoseInUnit(const Pose& pose) const {
    Pose scaled = pose;
    scaled.translation() *= PerMetre();
    return ArrayFromPose(scaled);
  }
  Eigen::Matrix<double, 12, 12> CovarianceInUnit(const Eigen::Matrix<double, 12, 12>& c) const {
    Eigen::Matrix<double, 12, 1> scale;
    for (int k = 0; k < 12; ++k) scale(k) = (k % 6) < 3 ? 1.0 : PerMetre();
    return scale.asDiagonal() * c * scale.asDiagonal();
  }
  py::dict Residual(const estimation::StationResidual& r, const std::string& id,
                    bool with_outlier) const {
    py::dict d;
    d["id"] = id;
    d["rotation"] = r.rotation;
    d["translation"] = r.translation * PerMetre();
    d["whitened"] = r.whitened;
    if (with_outlier) d["outlier"] = r.outlier;
    return d;
  }
};

std::string ToJson(const Result& r) {
  return report::FormatResult(*r.document, report::ResultFormat::kJson);
}

Result MakeResult(report::ResultDocument document) {
  Result out{std::make_shared<const report::ResultDocument>(std::move(document)), 0};
  // With every method: the default method's result first in line for the attributes.
  for (size_t k = 0; k < out.document->results.size(); ++k) {
    if (out.document->results[k].method == estimation::CalibrateOptions().method) out.index = k;
  }
  return out;
}

constexpr const char* kCalibrateDoc = R"doc(calibrate(robot, camera, setup=None, method="ml", ...) -> CalibrationResult

Solve the hand-eye calibration from robot poses and camera poses (`hecal calibrate`).

robot     Robot poses T_base_gripper (the gripper in the robot base frame), one per station:
          an (N, 4, 4) array, or the path of a pose file (docs/pose-files.md).
camera    Camera poses T_camera_target (the target in the camera frame): an (N, 4, 4) array
          (same station order), or the path of a pose file (paired by id, else by order).
setup     "eye-in-hand" (camera on the robot: X = T_gripper_camera, Z = T_base_target) |
          "eye-to-hand" (camera fixed: X = T_base_camera, Z = T_gripper_target) |
          "auto" or None (the setup the data fit, with the evidence in warnings).
method    Method name (default "ml"), or "all" (every method, compared; see results):
          tsai-lenz park-martin horaud horaud-nonlinear chou-kamel daniilidis andreff
          shiu-ahmad shah li strobl ml.
robot_sigma, camera_sigma
          Pose noise per axis as "MM,DEG" or (mm, deg) (estimated when absent).
units     Length unit "m" (default) or "mm": of pose-file columns without a suffix, and of
          arrays (unit= is the same; robot_unit= / camera_unit= set one array each). The
          result is in the robot poses' unit.
degrees   Pose files: angles without a suffix are in degrees.
euler     Pose files: Euler sequence of a1,a2,a3 columns (e.g. "ZYX", "xyz").
robot_inverse   The robot poses are T_gripper_base: invert every pose.
camera_inverse  The camera poses are T_target_camera: invert every pose.
keep_outliers   Use every station: no outlier rejection (by default gross outliers are
          rejected by consensus and a 3-sigma test, and listed).
all_methods     Every method, compared (method="all").
robust    Robust loss for ml: "none" | "huber" | "cauchy".
covariance  Covariance of X and Z: "linear" | "unscented" | "montecarlo" | "information"
          (default: linear for ml, unscented for the others up to 100 stations).
covariance_samples  Monte Carlo samples (2 to 100000). seed: random seed (Monte Carlo, the
          outlier consensus). threads: threads for covariance solves (0 = every core).
station_ids  One id per station (arrays only; default "0", "1", ...).
fix       Planar robots (every rotation about one axis: SCARA, mobile base, turntable): X's
          translation component along that axis, given, as "tz=0.09" (in units) or "tz=90mm";
          method ml only (docs/planar.md).

Returns a CalibrationResult: X, Z (4x4), covariance (12x12, right perturbation,
(rx, ry, rz, tx, ty, tz) of X then Z), sigma, residuals, rejected, noise, model_check,
warnings, setup, method, results (every method) and to_json() / to_dict(): the result file
`hecal calibrate --output` writes (docs/result-file.md).
Raises hecal.InputError (a ValueError: source, line, problem, fix) and hecal.DegenerateError.)doc";

}  // namespace

void RegisterCalibrate(py::module_& m) {
  py::class_<Result>(m, "CalibrationResult",
                     "The result of hecal.calibrate / hecal.calibrate_images (docs/result-file.md). "
                     "Lengths in `unit`, angles in radians.")
      .def_property_readonly("setup", [](const Result& r) {
        return std::string(handeye::SetupName(r.document->setup));
      }, "\"eye-in-hand\" or \"eye-to-hand\": the setup solved (the one auto picked)")
      .def_property_readonly("method", [](const Result& r) {
        return std::string(estimation::Info(r.result().method).name);
      }, "the method name")
      .def_property_readonly("unit", [](const Result& r) {
        return std::string(io::UnitName(r.document->unit));
      }, "length unit of every length of the result: \"m\" or \"mm\"")
      .def_property_readonly("X", [](const Result& r) { return r.PoseInUnit(r.result().X); },
                             "4x4: T_gripper_camera (eye-in-hand) or T_base_camera (eye-to-hand)")
      .def_property_readonly("Z", [](const Result& r) { return r.PoseInUnit(r.result().Z); },
                             "4x4: T_base_target (eye-in-hand) or T_gripper_target (eye-to-hand)")
      .def_property_readonly("X_frame", [](const Result& r) {
        return std::string(handeye::XFrameName(r.document->setup));
      })
      .def_property_readonly("Z_frame", [](const Result& r) {
        return std::string(handeye::ZFrameName(r.document->setup));
      })
      .def_property_readonly("covariance", [](const Result& r) -> py::object {
        if (!r.result().covariance) return py::none();
        return ArrayFromMatrix(r.CovarianceInUnit(r.result().covariance->covariance));
      }, "12x12 covariance of (dX, dZ), right perturbations X = X^ Exp(d), d = (rx, ry, rz, tx, "
         "ty, tz): rad^2, rad*unit, unit^2; None without a covariance")
      .def_property_readonly("sigma", [](const Result& r) -> py::object {
        if (!r.result().covariance) return py::none();
        const Eigen::Matrix<double, 12, 12> c = r.CovarianceInUnit(r.result().covariance->covariance);
        return ArrayFromMatrix(c.diagonal().cwiseSqrt());
      }, "12x1: 1-sigma per axis of (rx, ry, rz, tx, ty, tz) of X then Z (rad, unit), along "
         "each pose's own axes")
      .def_property_readonly("residuals", [](const Result& r) {
        py::list out;
        const std::vector<std::string> ids = report::UsedStationIds(*r.document);
        const auto& residuals = r.result().residuals;
        for (size_t i = 0; i < residuals.size(); ++i)
          out.append(r.Residual(residuals[i], i < ids.size() ? ids[i] : std::to_string(i), true));
        return out;
      }, "per used station: {id, rotation (rad), translation (unit), whitened, outlier}")
      .def_property_readonly("rotation_rms", [](const Result& r) { return r.result().rotation_rms; },
                             "rad")
      .def_property_readonly("translation_rms", [](const Result& r) {
        return r.result().translation_rms * r.PerMetre();
      }, "unit")
      .def_property_readonly("rejected", [](const Result& r) {
        py::list out;
        const auto& rejected = r.result().rejected;
        const auto& residuals = r.result().rejected_residuals;
        for (size_t k = 0; k < rejected.size(); ++k) {
          const size_t i = static_cast<size_t>(rejected[k]);
          const std::string id =
              i < r.document->station_ids.size() ? r.document->station_ids[i] : std::to_string(i);
          if (k < residuals.size()) {
            out.append(r.Residual(residuals[k], id, false));
          } else {
            py::dict d;
            d["id"] = id;
            out.append(d);
          }
        }
        return out;
      }, "the stations rejected as gross outliers: {id, rotation, translation, whitened} at "
         "the result")
      .def_property_readonly("station_ids", [](const Result& r) { return r.document->station_ids; })
      .def_property_readonly("used_station_ids", [](const Result& r) {
        return report::UsedStationIds(*r.document);
      })
      .def_property_readonly("noise", [](const Result& r) {
        const auto& c = r.result();
        py::dict d;
        d["robot_sigma"] = py::make_tuple(c.robot_sigma.rotation, c.robot_sigma.translation * r.PerMetre());
        d["camera_sigma"] = py::make_tuple(c.camera_sigma.rotation, c.camera_sigma.translation * r.PerMetre());
        d["estimated"] = c.sigmas_estimated;
        d["student_t_dof"] = c.student_t_dof;
        return d;
      }, "the noise model used: robot_sigma / camera_sigma (rad, unit) per axis, estimated, "
         "student_t_dof (0: Gaussian)")
      .def_property_readonly("model_check", [](const Result& r) -> py::object {
        const auto& check = r.result().model_check;
        if (!check) return py::none();
        py::dict d;
        d["possible"] = check->possible;
        d["reason"] = check->reason;
        d["groups"] = check->groups;
        d["sigma_model"] = ArrayFromMatrix(check->sigma_model);
        d["sigma_check"] = ArrayFromMatrix(check->sigma_check);
        d["ratio"] = ArrayFromMatrix(check->Ratio());
        py::list flagged;
        for (bool f : check->flagged) flagged.append(f);
        d["flagged"] = flagged;
        d["used"] = check->used;
        return d;
      }, "the jackknife check of the covariance (docs/result-file.md#covariancemodel_check); "
         "sigmas in rad and metres, (rx..tz) of X then Z")
      .def_property_readonly("warnings", [](const Result& r) { return r.result().warnings; })
      .def_property_readonly("seed", [](const Result& r) -> py::object {
        if (!r.result().seed) return py::none();
        return py::int_(*r.result().seed);
      })
      .def_property_readonly("results", [](const Result& r) {
        py::list out;
        for (size_t k = 0; k < r.document->results.size(); ++k) out.append(Result{r.document, k});
        return out;
      }, "one result per method (method=\"all\"); [self] otherwise")
      .def_property_readonly("failures", [](const Result& r) {
        py::dict d;
        for (const auto& f : r.document->failures)
          d[py::str(std::string(estimation::Info(f.method).name))] = f.message;
        return d;
      }, "method=\"all\": the methods that refused the data, with why")
      .def("to_json", &ToJson,
           "The result file `hecal calibrate --output out.json` writes (docs/result-file.md)")
      .def("to_yaml", [](const Result& r) {
        return report::FormatResult(*r.document, report::ResultFormat::kYaml);
      }, "The same as YAML (--output out.yaml)")
      .def("to_dict", [](const Result& r) {
        return py::module_::import("json").attr("loads")(ToJson(r));
      }, "json.loads(to_json())")
      .def("__repr__", [](const Result& r) {
        const Pose& X = r.result().X;
        const Eigen::Vector3d t = X.translation() * r.PerMetre();
        return "<hecal.CalibrationResult " + std::string(handeye::SetupName(r.document->setup)) +
               " " + std::string(estimation::Info(r.result().method).name) + ": X = " +
               std::string(handeye::XFrameName(r.document->setup)) + ", t = (" +
               std::to_string(t.x()) + ", " + std::to_string(t.y()) + ", " +
               std::to_string(t.z()) + ") " + std::string(io::UnitName(r.document->unit)) + ">";
      });

  m.def(
      "calibrate",
      [](py::handle robot, py::handle camera, std::optional<std::string> setup,
         std::string method, py::handle robot_sigma, py::handle camera_sigma,
         std::optional<std::string> units, std::optional<std::string> unit,
         std::optional<std::string> robot_unit, std::optional<std::string> camera_unit,
         bool degrees, std::optional<std::string> euler, bool robot_inverse, bool camera_inverse,
         bool keep_outliers, bool all_methods, std::string robust,
         std::optional<std::string> covariance, int covariance_samples, std::uint64_t seed,
         int threads, std::optional<std::vector<std::string>> station_ids,
         std::optional<std::string> fix) {
        const bool all = all_methods || method == "all";
        estimation::CalibrateOptions options = CalibrateOptionsFromArguments(
            all ? "all" : method, robot_sigma, camera_sigma, keep_outliers, robust, covariance,
            covariance_samples, seed, threads);
        if (units && unit && *units != *unit) {
          ThrowArgument("unit", "unit='" + *unit + "' and units='" + *units + "' disagree",
                        "give one of them");
        }
        const std::optional<std::string> both = unit ? unit : units;
        if (fix) {
          const io::LengthUnit fix_unit =
              ParseUnitArgument("units", both).value_or(io::LengthUnit::kMetre);
          options.fix = handeye::ParseTranslationFix(*fix, io::MetresPer(fix_unit),
                                                     io::UnitName(fix_unit), "fix");
          if (all) ThrowArgument("fix", "every method is run, and only ml takes fix", "use method=\"ml\"");
        }

        const auto robot_path = AsPath(robot);
        const auto camera_path = AsPath(camera);
        if (robot_path.has_value() != camera_path.has_value()) {
          ThrowArgument(robot_path ? "camera" : "robot",
                        "is an array while the other poses are a file",
                        "give both as files or both as (N, 4, 4) arrays");
        }
        report::ResultDocument document;
        if (robot_path) {
          if (robot_unit || camera_unit || station_ids) {
            ThrowArgument(robot_unit ? "robot_unit" : camera_unit ? "camera_unit" : "station_ids",
                          "applies to arrays only",
                          "for pose files give units= (columns without a suffix) or ids in the "
                          "files' id column");
          }
          jobs::PoseFileCalibrationOptions job;
          job.robot = *robot_path;
          job.camera = *camera_path;
          io::PoseReadOptions read;
          read.units = ParseUnitArgument("units", both).value_or(io::LengthUnit::kMetre);
          read.degrees = degrees;
          read.euler = ParseEulerArgument(euler);
          job.robot_read = read;
          job.robot_read.invert = robot_inverse;
          job.camera_read = read;
          job.camera_read.invert = camera_inverse;
          job.setup = ParseSetupArgument(setup);
          job.calibrate = options;
          job.all_methods = all;
          job.words = PythonWords();
          job.file_words = {"robot=", "camera="};
          py::gil_scoped_release release;
          document = jobs::CalibrateFromPoseFiles(job).document;
        } else {
          if (degrees || euler) {
            ThrowArgument(degrees ? "degrees" : "euler", "applies to pose files only",
                          "arrays are 4x4 transforms: leave it out");
          }
          std::vector<Pose> robot_poses = PosesFromArray(robot, "robot");
          std::vector<Pose> camera_poses = PosesFromArray(camera, "camera");
          if (robot_inverse)
            for (Pose& T : robot_poses) T = T.inverse();
          if (camera_inverse)
            for (Pose& T : camera_poses) T = T.inverse();
          jobs::PoseCalibrationOptions job;
          job.setup = ParseSetupArgument(setup);
          job.robot_unit = ParseUnitArgument("robot_unit", robot_unit ? robot_unit : both);
          job.camera_unit = ParseUnitArgument("camera_unit", camera_unit ? camera_unit : both);
          job.calibrate = options;
          job.all_methods = all;
          if (station_ids) {
            job.station_ids = *station_ids;
          } else {
            for (size_t i = 0; i < robot_poses.size(); ++i) job.station_ids.push_back(std::to_string(i));
          }
          job.robot_source = "robot";
          job.camera_source = "camera";
          job.words = PythonWords();
          py::gil_scoped_release release;
          document = jobs::CalibratePoses(robot_poses, camera_poses, job).document;
        }
        return MakeResult(std::move(document));
      },
      py::arg("robot"), py::arg("camera"), py::kw_only(), py::arg("setup") = py::none(),
      py::arg("method") = "ml", py::arg("robot_sigma") = py::none(),
      py::arg("camera_sigma") = py::none(), py::arg("units") = py::none(),
      py::arg("unit") = py::none(), py::arg("robot_unit") = py::none(),
      py::arg("camera_unit") = py::none(), py::arg("degrees") = false,
      py::arg("euler") = py::none(), py::arg("robot_inverse") = false,
      py::arg("camera_inverse") = false, py::arg("keep_outliers") = false,
      py::arg("all_methods") = false, py::arg("robust") = "none",
      py::arg("covariance") = py::none(), py::arg("covariance_samples") = 5000,
      py::arg("seed") = 1, py::arg("threads") = 0, py::arg("station_ids") = py::none(),
      py::arg("fix") = py::none(), kCalibrateDoc);
}

// For calibrate_images (images.cc): the same result object.
py::object WrapDocument(report::ResultDocument document) {
  return py::cast(MakeResult(std::move(document)));
}

}  // namespace hecal::python
