// `hecal contour` and `hecal contour pose`: see contour.h. The flags bind typed values into
// contour::ShapePoseOptions (numbers read by bounds.h's rule, so a bad number names its flag);
// its IsValid checks the camera, Σ_S and w0 (field_flags.h names the flag).
#include "contour.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>
#include <vector>

#include "bounds.h"
#include "choice_flags.h"
#include "hecal/hecal.h"

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

// `contour pose`: the shape vector and the library's options, typed.
struct ContourPoseCommand {
  Vector6d shape = Vector6d::Zero();
  contour::ShapePoseOptions options;
  bool json = false;
};

void RunContourPose(const ContourPoseCommand& command, const Io& io) {
  const contour::ShapePose result = contour::EstimateShapePose(command.shape, command.options);
  if (command.json) {
    io.out << report::ContourPoseJson(result);
    return;
  }
  report::PrintContourPose(io.out, result);
}

// Binds `flag` to the number `value` by bounds.h's rule (ParseNumber: a bad number names the
// flag); `what` describes it in the fix.
CLI::Option* AddNumber(CLI::App& command, const std::string& flag, double& value,
                       const std::string& what, const std::string& help) {
  return command.add_option_function<std::string>(
      flag,
      [flag, what, &value](const std::string& text) { value = ParseNumber(flag, text, what); },
      help);
}

}  // namespace

CLI::Option* AddRotationFlag(CLI::App& command, contour::RotationForm& form) {
  return AddChoice<contour::RotationForm>(command, "--rotation", form, contour::ParseRotationForm,
                                          "rotation form",
                                          "zyx (roll–pitch–yaw, the contour paper's choice) or zxz",
                                          "zyx (default; roll–pitch–yaw) or zxz");
}

void RegisterContourCommand(CLI::App& app, const Io& io) {
  CLI::App* contour = app.add_subcommand(
      "contour", "Camera motion from the affine deformation of a planar contour (docs/contour.md)");
  contour->require_subcommand(1);

  auto command = std::make_shared<ContourPoseCommand>();
  contour::ShapePoseOptions& o = command->options;
  CLI::App* pose = contour->add_subcommand("pose", "The camera motion of one shape vector");
  pose->add_option_function<std::string>(
          "--shape",
          [command](const std::string& text) {
            const std::vector<double> s =
                ParseNumberList("--shape", text, 6, "tx,ty,m11m1,m22m1,m21,m12");
            command->shape = Eigen::Map<const Vector6d>(s.data());
          },
          "tx,ty,m11m1,m22m1,m21,m12: S = (tx, ty, M11−1, M22−1, M21, M12), tx, ty in "
          "the unit of --focal (use --shape=… when it starts with '-')")
      ->required()
      ->allow_extra_args(false);
  AddNumber(*pose, "--z0", o.camera.z0, "the initial distance Z0",
            "Initial distance Z0 (the unit of the translation)")
      ->required();
  AddNumber(*pose, "--focal", o.camera.focal, "the focal length",
            "Focal length F (the unit of tx, ty)")
      ->required();
  AddRotationFlag(*pose, o.form);
  pose->add_flag("--json", command->json, "Print JSON");
  pose->add_option_function<std::string>(
      "--covariance",
      [&o](const std::string& text) { o.shape_covariance = ParseShapeCovariance(text); },
      "Σ_S: 6 variances or 36 row-major entries → UT pose covariance");
  pose->add_option_function<std::string>(
      "--ut-w0",
      [&o](const std::string& text) {
        o.unscented.unscented =
            uncertainty::UnscentedParameters::Symmetric(ParseNumber("--ut-w0", text, "w0 < 1"));
      },
      "UT centre weight w0 (default 0)");
  pose->callback([command, io] { RunContourPose(*command, io); });

  AddContourStudyCommand(*contour, io);
  AddContourTrackCommand(*contour, io);
  AddContourRenderCommand(*contour, io);
}

}  // namespace hecal::cli
