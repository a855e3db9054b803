// The 1σ of a pose's translation along its PARENT frame's axes — the axes its translation is
// printed and written in — from the pose's right-perturbation covariance (docs/uncertainty.md,
// docs/result-file.md).
//
// Why: every covariance hecal reports is of δ = (ω, v) in T = T̂ · Exp(δ), expressed in T̂'s own
// (child) frame (docs/conventions.md, "Perturbations and covariances"). For X = T_gripper_camera
// its translation σ (`covariance.sigma.X.translation`, the `1σ X` line) is along the CAMERA's
// axes, while t = X's translation is in the GRIPPER's frame. Reading the two axis by axis is
// wrong whenever R̂ is not the identity (docs/global.md: on rwhe-kuka2 the camera's x is the
// gripper's −y and a per-axis reading misjudges t's x by 3.4×).
//
// Derivation (SE(3) tangent, the convention se3.h implements): T̂ · Exp(ω, v) has translation
//   t = t̂ + R̂ · Jl(ω) · v,   Jl(ω) = I + ½[ω]× + O(|ω|²),
// so t − t̂ = R̂ v + ½ R̂ (ω × v) + …: to first order t − t̂ = R̂ v, and
//   Cov(t) = R̂ · C_vv · R̂ᵀ      (C_vv the translation block, rows and columns 3..5).
// The rotation–translation cross terms C_ωv do NOT enter at first order under the right
// perturbation (they would under the left one, t = Exp(ω) t̂ + v, through −[t̂]× ω); they enter
// only at second order, through the bias ½ R̂ E[ω × v], negligible at the σ a calibration has.
// Under SO(3) × R³ (t = t̂ + R̂ v exactly) the same formula is exact.
//
// Units: the covariance in radians and metres (the library's units); the printout in millimetres,
// the JSON field in the document's length unit (`scale` = that unit per metre).
// ParentFrame names the frame of "T_a_b" (docs/conventions.md): "a"; a name not of that form
// is a programming error (the frame names come from handeye::XFrameName / ZFrameName).
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string_view>

#include "hecal/geometry/types.h"

namespace hecal::report {

// R̂ C_vv R̂ᵀ: the first-order covariance of T's translation in T's parent frame.
Eigen::Matrix3d TranslationCovarianceInParent(const Pose& T, const Matrix6d& covariance);

// "T_gripper_camera" → "gripper".
std::string_view ParentFrame(std::string_view pose_name);

// One line, e.g. `  1σ of X's translation along the gripper's axes: (1.8 0.5 0.4) mm`, where
// `pose_name` is X's frame name ("T_gripper_camera").
void PrintTranslationSigmaInParent(std::ostream& out, std::string_view name,
                                   std::string_view pose_name, const Pose& T,
                                   const Matrix6d& covariance);

// {"frame": "gripper", "translation": [σx, σy, σz]} in the output unit (scale = unit per metre).
nlohmann::json TranslationSigmaInParentJson(std::string_view pose_name, const Pose& T,
                                            const Matrix6d& covariance, double scale);

}  // namespace hecal::report
