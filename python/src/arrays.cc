// NumPy arrays ↔ hecal poses and matrices, and paths (bindings.h): the conversions every other
// file of the module uses. Pose arrays are N×4×4, homogeneous T_a_b (row-major rows, the last row
// 0 0 0 1), any float dtype and strides in, float64 out.
#include <cmath>
#include <string>

#include "bindings.h"

namespace hecal::python {

std::vector<Pose> PosesFromArray(const py::handle& object, const std::string& argument) {
  py::array_t<double, py::array::forcecast> array;
  try {
    array = py::array_t<double, py::array::forcecast>::ensure(object);
  } catch (const py::error_already_set&) {
  }
  if (!array) {
    PyErr_Clear();
    ThrowArgument(argument, "is neither an N×4×4 array of poses nor a pose file path",
                  "give a NumPy array of shape (N, 4, 4) (homogeneous transforms) or the path of "
                  "a pose file");
  }
  if (array.ndim() != 3 || array.shape(1) != 4 || array.shape(2) != 4) {
    std::string shape = "(";
    for (py::ssize_t k = 0; k < array.ndim(); ++k)
      shape += (k ? ", " : "") + std::to_string(array.shape(k));
    ThrowArgument(argument, "has shape " + shape + (array.ndim() == 1 ? ",)" : ")"),
                  "give an array of shape (N, 4, 4): one homogeneous transform per station");
  }
  const auto a = array.unchecked<3>();
  std::vector<Pose> poses(static_cast<size_t>(a.shape(0)));
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    Eigen::Matrix4d T;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) T(r, c) = a(i, r, c);
    if (T.allFinite() && (T.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9) {
      ThrowArgument(argument,
                    "pose " + std::to_string(i) + " has the last row (" + std::to_string(T(3, 0)) +
                        ", " + std::to_string(T(3, 1)) + ", " + std::to_string(T(3, 2)) + ", " +
                        std::to_string(T(3, 3)) + ") instead of (0, 0, 0, 1)",
                    "give homogeneous 4×4 transforms");
    }
    Pose& pose = poses[static_cast<size_t>(i)];
    pose.matrix() = T;  // rotation checks: the job's (finite, proper rotation)
  }
  return poses;
}

py::array_t<double> ArrayFromPoses(const std::vector<Pose>& poses) {
  py::array_t<double> out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{4}, py::ssize_t{4}});
  auto a = out.mutable_unchecked<3>();
  for (size_t i = 0; i < poses.size(); ++i)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) a(static_cast<py::ssize_t>(i), r, c) = poses[i].matrix()(r, c);
  return out;
}

py::array_t<double> ArrayFromPose(const Pose& pose) {
  return ArrayFromMatrix(pose.matrix());
}

py::array_t<double> ArrayFromMatrix(const Eigen::MatrixXd& matrix) {
  py::array_t<double> out({static_cast<py::ssize_t>(matrix.rows()),
                           static_cast<py::ssize_t>(matrix.cols())});
  auto a = out.mutable_unchecked<2>();
  for (Eigen::Index r = 0; r < matrix.rows(); ++r)
    for (Eigen::Index c = 0; c < matrix.cols(); ++c) a(r, c) = matrix(r, c);
  return out;
}

std::optional<std::string> AsPath(const py::handle& object) {
  if (py::isinstance<py::str>(object)) return object.cast<std::string>();
  if (py::hasattr(object, "__fspath__")) {
    py::object path = object.attr("__fspath__")();
    if (py::isinstance<py::str>(path)) return path.cast<std::string>();
  }
  return std::nullopt;
}

}  // namespace hecal::python
