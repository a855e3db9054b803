// What the files of the Python module share (docs/python.md): the registration function of each
// concept (one per file of python/src) and the small conversions between NumPy and hecal's types.
// The module includes only hecal/hecal.h from hecal (the front door).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "hecal/hecal.h"

namespace hecal::python {

namespace py = pybind11;

// errors.cc: hecal.Error, hecal.InputError (also a ValueError: .source, .line, .problem, .fix)
// and hecal.DegenerateError (.unobservable); C++ errors become them.
void RegisterErrors(py::module_& m);
// drop_in.cc: calibrateHandEye, calibrateRobotWorldHandEye and OpenCV's method constants.
void RegisterDropIn(py::module_& m);
// calibrate.cc: calibrate (poses in memory or pose files) and its result object.
void RegisterCalibrate(py::module_& m);
// poses.cc: read_poses, write_poses.
void RegisterPoses(py::module_& m);
// images.cc: calibrate_images, detect (when the vision layer is built).
void RegisterImages(py::module_& m);
// simulate.cc: simulate (the thesis study).
void RegisterSimulate(py::module_& m);

// An InputError whose source is a Python argument (line 0).
[[noreturn]] void ThrowArgument(const std::string& argument, const std::string& problem,
                                const std::string& fix);

// N×4×4 float array (any float dtype, any strides) → poses; InputError naming `argument` for
// another shape or a last row other than 0 0 0 1.
std::vector<Pose> PosesFromArray(const py::handle& array, const std::string& argument);
// Poses → a new N×4×4 float64 array.
py::array_t<double> ArrayFromPoses(const std::vector<Pose>& poses);
// A 4×4 float64 array of a pose; an R×C float64 array of any Eigen matrix.
py::array_t<double> ArrayFromPose(const Pose& pose);
py::array_t<double> ArrayFromMatrix(const Eigen::MatrixXd& matrix);

// A str or os.PathLike as a path; nullopt for anything else.
std::optional<std::string> AsPath(const py::handle& object);

}  // namespace hecal::python

namespace hecal::python {
// calibrate.cc: a result document as a hecal.CalibrationResult (calibrate_images shares it).
py::object WrapDocument(report::ResultDocument document);
}  // namespace hecal::python

namespace hecal::python {
// calibrate.cc: the keyword arguments every calibration shares, as the CLI's flags parse them.
handeye::ConventionWords PythonWords();
std::optional<handeye::Setup> ParseSetupArgument(const std::optional<std::string>& setup);
std::optional<io::LengthUnit> ParseUnitArgument(const std::string& argument,
                                                const std::optional<std::string>& text);
std::optional<estimation::PoseSigma> ParseSigmaArgument(const std::string& argument,
                                                        const py::handle& value);
std::optional<EulerSequence> ParseEulerArgument(const std::optional<std::string>& euler);
// method "all" leaves the default method (the caller runs every method).
estimation::CalibrateOptions CalibrateOptionsFromArguments(
    const std::string& method, py::handle robot_sigma, py::handle camera_sigma,
    bool keep_outliers, const std::string& robust, const std::optional<std::string>& covariance,
    int covariance_samples, std::uint64_t seed, int threads);
}  // namespace hecal::python
