// Gross outliers for robustness studies: stations whose robot pose is replaced by an arbitrary
// pose (a wrong row, a pose recorded before the robot settled, a pairing slip) — the thesis
// protocol's data (thesis_protocol.h) with k such stations.
//
// The replaced stations are k distinct stations drawn uniformly; each gets a random robot pose:
// a uniformly distributed rotation (a normalised 4-D Gaussian quaternion; Shoemake, "Uniform
// random rotations", Graphics Gems III, 1992) and a translation uniform in [−1, 1]³ m, the
// scale of the protocol's poses. The camera pose of the station is kept.
#pragma once

#include <random>
#include <vector>

#include "hecal/sim/thesis_protocol.h"

namespace hecal::sim {

// Replaces the measured robot pose (data->T_base_gripper) of `count` distinct stations and returns
// their indices, ascending. Requires 0 ≤ count ≤ the number of stations.
std::vector<int> InjectGrossOutliers(SimulatedData* data, int count, std::mt19937_64& rng);

}  // namespace hecal::sim
