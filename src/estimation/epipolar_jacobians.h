// Internal (not installed): the angular Sampson residuals r̂ of the target-free problem at X
// (epipolar_residual.h) and their Jacobians J in δ, the right perturbation of X, and G in every
// station's hand-pose perturbation η, one row per bearing pair in the order of the motions; used
// by the robot-noise polish and its jackknife (epipolar_robot_noise.cc).
#pragma once

#include <Eigen/Core>
#include <map>

#include "hecal/geometry/types.h"
#include "hecal/global/epipolar_problem.h"

namespace hecal::estimation::detail {

struct EpipolarJacobians {
  Eigen::MatrixXd J;  // n × 6
  Eigen::MatrixXd G;  // n × 6s, the stations in the order of EpipolarStationIndex
  Eigen::VectorXd r;  // n
};

// Each station of the problem's motions → its index, in the order first met.
std::map<int, int> EpipolarStationIndex(const global::EpipolarProblem& problem);

// Throws hecal::DegenerateError below 7 bearing pairs (X has 6 unknowns).
EpipolarJacobians DifferentiateEpipolar(const global::EpipolarProblem& problem, const Pose& X);

}  // namespace hecal::estimation::detail
