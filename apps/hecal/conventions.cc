// The command line's side of the convention check: see conventions.h.
#include "conventions.h"

namespace hecal::cli {

handeye::ConventionWords ConventionFlagWords() {
  handeye::ConventionWords words;
  words.setup = "--setup";
  words.units = "--units";
  words.invert_robot = "add --robot-inverse";
  words.keep_robot = "leave out --robot-inverse";
  words.invert_camera = "add --camera-inverse";
  words.keep_camera = "leave out --camera-inverse";
  words.import_matrix_lines = "hecal import --format matrix16";
  return words;
}

}  // namespace hecal::cli
