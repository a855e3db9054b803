// The robot pose of every image station (`hecal calibrate --images`, docs/targets.md#the-image-
// folder---images-dir): when every robot row has an id and some id is a station's id (the image's
// file stem or its sub-folder's name, io/image_files.h), the rows pair with the stations by id —
// each station needs a row, rows without a station are left out with a note; otherwise by order
// — one row per station, in the stations' sorted order (stations whose target is not usable count
// too), and ids that name no station (such as the row numbers `hecal import` writes) get a note.
// Poses are the table's T_base_gripper (metres).
//
// Errors (hecal::InputError naming the robot file): by order, a row count other than the
// station count (both named); by id, an id that repeats (its line and the first), a station
// without a row (naming the image).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/io/image_files.h"
#include "hecal/io/pose_table.h"

namespace hecal::io {

// One pose per station of `stations`, in their order. `images_dir` names the folder in
// messages; `note` receives each note as it arises (may be empty).
std::vector<Pose> PairRobotWithStations(const PoseTable& robot,
                                        const std::vector<StationImage>& stations,
                                        const std::string& images_dir,
                                        const std::function<void(const std::string&)>& note);

}  // namespace hecal::io
