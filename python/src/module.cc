// The compiled module `hecal._hecal`, re-exported by python/hecal/__init__.py (docs/python.md):
// every concept registers itself from its own file (bindings.h).
#include "bindings.h"

PYBIND11_MODULE(_hecal, m) {
  using namespace hecal::python;
  m.doc() =
      "hecal: hand-eye calibration with honest uncertainty (docs/python.md).\n\n"
      "Conventions: T_a_b maps coordinates in frame b to frame a; lengths in metres (or the "
      "unit given), angles in radians; covariances of right perturbations, (rx, ry, rz, tx, ty, "
      "tz) per pose.";
  m.attr("__version__") = hecal::kVersion;
  // Every docstring starts with its own signature in Python terms (the CLI-like help); pybind11's
  // generated one would show C++ argument types.
  pybind11::options options;
  options.disable_function_signatures();
  RegisterErrors(m);
  RegisterDropIn(m);
  RegisterCalibrate(m);
  RegisterPoses(m);
  RegisterImages(m);
  RegisterSimulate(m);
}
