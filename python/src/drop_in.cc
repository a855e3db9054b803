// The OpenCV drop-in (docs/python.md#the-opencv-drop-in): hecal.calibrateHandEye and
// hecal.calibrateRobotWorldHandEye with OpenCV 4.6's positional and keyword forms and return
// tuples, solved by jobs::CalibrateHandEyeDropIn / CalibrateRobotWorldHandEyeDropIn
// (hecal/jobs/opencv_drop_in.h), and the method constants CALIB_HAND_EYE_* and
// CALIB_ROBOT_WORLD_HAND_EYE_* (OpenCV's values) plus CALIB_HAND_EYE_ML (hecal's ml, the default).
//
// Inputs, parsed here in C++ through the buffer protocol (no Python loop): a list or tuple of
// 3×3 rotation matrices or Rodrigues vectors shaped (3,), (3,1) or (1,3), or one array N×3×3,
// N×3×1, N×1×3 or N×3 (Rodrigues vectors); translations (3,), (3,1), (1,3) each, or one array
// N×3, N×3×1 or N×1×3; float32 or float64 (other numbers are converted). Outputs: 3×3 and 3×1
// float64 arrays; an output argument given as a C-contiguous float64 array of that size is filled
// and returned, as OpenCV does.
// Refused with hecal.InputError where OpenCV 4.6 is silent: anything but None or an array in an
// output slot — notably the method integer passed positionally into R_cam2gripper (opencv#27625,
// OpenCV then runs TSAI) — and what the job refuses (unknown method, < 3 poses, lengths, NaN, a
// matrix that is not a rotation). The GIL is released while the job runs.
#include <cstring>
#include <optional>
#include <string>
#include <utility>

#include "bindings.h"

namespace hecal::python {
namespace {

// A read-only strided view of a Python buffer of float64 or float32 (others converted first).
class Buffer {
 public:
  Buffer() = default;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer() { Release(); }

  // False when `object` is not a buffer of numbers (the caller names the argument).
  bool Acquire(py::handle object) {
    Release();
    if (TryView(object.ptr()) && (format_ == 'd' || format_ == 'f')) return true;
    Release();
    // Nested lists, integers, other float types: NumPy converts them to float64.
    PyObject* converted = PyObject_CallFunctionObjArgs(AsArray(), object.ptr(), Float64(), nullptr);
    if (converted == nullptr) {
      PyErr_Clear();
      return false;
    }
    converted_ = py::reinterpret_steal<py::object>(converted);
    if (TryView(converted) && format_ == 'd') return true;
    Release();
    return false;
  }

  int ndim() const { return view_.ndim; }
  Py_ssize_t shape(int k) const { return view_.shape[k]; }
  Py_ssize_t size() const {
    Py_ssize_t n = 1;
    for (int k = 0; k < view_.ndim; ++k) n *= view_.shape[k];
    return n;
  }
  std::string ShapeText() const {
    std::string text = "(";
    for (int k = 0; k < view_.ndim; ++k) {
      if (k > 0) text += ", ";
      text += std::to_string(view_.shape[k]);
    }
    return text + (view_.ndim == 1 ? ",)" : ")");
  }
  // Element at a multi-index of ndim() entries.
  double At(std::initializer_list<Py_ssize_t> index) const {
    const char* p = static_cast<const char*>(view_.buf);
    int k = 0;
    for (Py_ssize_t i : index) p += i * view_.strides[k++];
    if (format_ == 'd') {
      double value;
      std::memcpy(&value, p, sizeof value);
      return value;
    }
    float value;
    std::memcpy(&value, p, sizeof value);
    return value;
  }
  // The k-th element in row-major order of a buffer of 3 or 9 elements (any shape).
  double Flat(Py_ssize_t k) const {
    const char* p = static_cast<const char*>(view_.buf);
    Py_ssize_t rest = k;
    for (int d = view_.ndim - 1; d >= 0; --d) {
      p += (rest % view_.shape[d]) * view_.strides[d];
      rest /= view_.shape[d];
    }
    if (format_ == 'd') {
      double value;
      std::memcpy(&value, p, sizeof value);
      return value;
    }
    float value;
    std::memcpy(&value, p, sizeof value);
    return value;
  }

 private:
  static PyObject* AsArray() {
    static PyObject* function =
        py::object(py::module_::import("numpy").attr("asarray")).release().ptr();
    return function;
  }
  static PyObject* Float64() {
    static PyObject* dtype =
        py::object(py::module_::import("numpy").attr("float64")).release().ptr();
    return dtype;
  }
  bool TryView(PyObject* object) {
    if (!PyObject_CheckBuffer(object)) return false;
    if (PyObject_GetBuffer(object, &view_, PyBUF_RECORDS_RO) != 0) {
      PyErr_Clear();
      return false;
    }
    held_ = true;
    const char* f = view_.format == nullptr ? "B" : view_.format;
    if (*f == '<' || *f == '=' || *f == '@') ++f;  // native little-endian (x86, ARM)
    format_ = (std::strlen(f) == 1 && view_.itemsize == (*f == 'd'   ? 8
                                                         : *f == 'f' ? 4
                                                                     : -1))
                  ? *f
                  : '?';
    return true;
  }
  void Release() {
    if (held_) PyBuffer_Release(&view_);
    held_ = false;
    converted_ = py::object();
  }

  Py_buffer view_{};
  bool held_ = false;
  char format_ = '?';
  py::object converted_;
};

bool IsVectorShape(const Buffer& b) {
  return (b.ndim() == 1 && b.shape(0) == 3) ||
         (b.ndim() == 2 &&
          ((b.shape(0) == 3 && b.shape(1) == 1) || (b.shape(0) == 1 && b.shape(1) == 3)));
}

[[noreturn]] void NotAList(const std::string& name, const char* what) {
  ThrowArgument(name, std::string("is not a list of ") + what,
                "give a list or tuple of NumPy arrays, or one NumPy array with one row per pose");
}

// Calls each(i, buffer) for every entry of a list or tuple, each entry acquired as a buffer of
// numbers (an error naming the entry otherwise); `numbers` says what the entries should be.
template <class Each>
void ForEachEntry(py::handle list, const std::string& name, const char* numbers, Each&& each) {
  const py::sequence items = py::reinterpret_borrow<py::sequence>(list);
  Buffer b;
  for (size_t i = 0; i < items.size(); ++i) {
    PyObject* item = PySequence_Fast_GET_ITEM(items.ptr(), static_cast<Py_ssize_t>(i));
    if (!b.Acquire(item)) {
      ThrowArgument(name, "entry " + std::to_string(i) + " is not an array of numbers",
                    std::string("give ") + numbers + " as NumPy arrays");
    }
    each(i, b);
  }
}

bool IsList(py::handle object) {
  return PyList_Check(object.ptr()) || PyTuple_Check(object.ptr());
}

// Rotations: a list/tuple of 3×3 or Rodrigues-vector items, or one N×3×3 / N×3×1 / N×1×3 / N×3
// array.
std::vector<jobs::DropInRotation> ParseRotations(py::handle object, const std::string& name) {
  std::vector<jobs::DropInRotation> out;
  if (IsList(object)) {
    out.resize(py::len(object));
    ForEachEntry(
        object, name, "3×3 rotation matrices or Rodrigues vectors", [&](size_t i, Buffer& b) {
          jobs::DropInRotation& r = out[i];
          if (b.ndim() == 2 && b.shape(0) == 3 && b.shape(1) == 3) {
            for (int row = 0; row < 3; ++row)
              for (int col = 0; col < 3; ++col) r.matrix(row, col) = b.At({row, col});
          } else if (IsVectorShape(b)) {
            r.is_vector = true;
            for (int k = 0; k < 3; ++k) r.vector(k) = b.Flat(k);
          } else {
            ThrowArgument(name, "entry " + std::to_string(i) + " has shape " + b.ShapeText(),
                          "give 3×3 rotation matrices or Rodrigues vectors shaped (3,), (3, 1) or "
                          "(1, 3)");
          }
        });
    return out;
  }
  Buffer b;
  if (!b.Acquire(object) || b.ndim() == 0) NotAList(name, "rotations");
  const bool matrices = b.ndim() == 3 && b.shape(1) == 3 && b.shape(2) == 3;
  const bool vectors3 = b.ndim() == 3 && ((b.shape(1) == 3 && b.shape(2) == 1) ||
                                          (b.shape(1) == 1 && b.shape(2) == 3));
  const bool vectors2 = b.ndim() == 2 && b.shape(1) == 3;
  if (!matrices && !vectors3 && !vectors2) {
    ThrowArgument(name, "has shape " + b.ShapeText(),
                  "give an N×3×3 array of rotation matrices, an N×3 array of Rodrigues vectors, "
                  "or a list of them");
  }
  out.resize(static_cast<size_t>(b.shape(0)));
  for (Py_ssize_t i = 0; i < b.shape(0); ++i) {
    jobs::DropInRotation& r = out[static_cast<size_t>(i)];
    if (matrices) {
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) r.matrix(row, col) = b.At({i, row, col});
    } else {
      r.is_vector = true;
      for (int k = 0; k < 3; ++k) {
        r.vector(k) = vectors2 ? b.At({i, k}) : b.shape(1) == 3 ? b.At({i, k, 0}) : b.At({i, 0, k});
      }
    }
  }
  return out;
}

// Translations: a list/tuple of (3,), (3,1), (1,3) items, or one N×3 / N×3×1 / N×1×3 array.
std::vector<Eigen::Vector3d> ParseTranslations(py::handle object, const std::string& name) {
  std::vector<Eigen::Vector3d> out;
  if (IsList(object)) {
    out.resize(py::len(object));
    ForEachEntry(object, name, "translation vectors", [&](size_t i, Buffer& b) {
      if (!IsVectorShape(b)) {
        ThrowArgument(name, "entry " + std::to_string(i) + " has shape " + b.ShapeText(),
                      "give translations shaped (3,), (3, 1) or (1, 3)");
      }
      for (int k = 0; k < 3; ++k) out[i](k) = b.Flat(k);
    });
    return out;
  }
  Buffer b;
  if (!b.Acquire(object) || b.ndim() == 0) NotAList(name, "translations");
  const bool rows = b.ndim() == 2 && b.shape(1) == 3;
  const bool columns = b.ndim() == 3 && ((b.shape(1) == 3 && b.shape(2) == 1) ||
                                         (b.shape(1) == 1 && b.shape(2) == 3));
  if (!rows && !columns) {
    ThrowArgument(name, "has shape " + b.ShapeText(),
                  "give an N×3 array of translations, or a list of (3,) / (3, 1) arrays");
  }
  out.resize(static_cast<size_t>(b.shape(0)));
  for (Py_ssize_t i = 0; i < b.shape(0); ++i) {
    for (int k = 0; k < 3; ++k) {
      out[static_cast<size_t>(i)](k) = rows              ? b.At({i, k})
                                       : b.shape(1) == 3 ? b.At({i, k, 0})
                                                         : b.At({i, 0, k});
    }
  }
  return out;
}

jobs::DropInPoses ParsePoses(py::handle R, py::handle t, const std::string& frames) {
  jobs::DropInPoses poses;
  poses.R_name = "R_" + frames;
  poses.t_name = "t_" + frames;
  poses.R = ParseRotations(R, poses.R_name);
  poses.t = ParseTranslations(t, poses.t_name);
  return poses;
}

int ParseMethod(py::handle method, const std::string& function) {
  if (PyBool_Check(method.ptr()) || !PyIndex_Check(method.ptr())) {
    ThrowArgument("method",
                  "is not an integer (got " +
                      std::string(py::str(py::type::handle_of(method).attr("__name__"))) + ")",
                  "pass one of the " + function + " method constants, e.g. method=" +
                      (function == "calibrateHandEye" ? "hecal.CALIB_HAND_EYE_PARK"
                                                      : "hecal.CALIB_ROBOT_WORLD_HAND_EYE_SHAH"));
  }
  const long long value = PyLong_AsLongLong(method.ptr());
  if (value == -1 && PyErr_Occurred()) {
    PyErr_Clear();
    ThrowArgument("method", "is out of range", "pass one of the method constants");
  }
  if (value < INT_MIN || value > INT_MAX) {
    ThrowArgument("method", "unknown method " + std::to_string(value),
                  "pass one of the method constants");
  }
  return static_cast<int>(value);
}

// An output slot: None, or an array (filled when it is a C-contiguous float64 array of `size`
// elements). Anything else is refused: OpenCV ignores an int there (opencv#27625).
std::optional<py::array_t<double>> OutputSlot(py::handle slot, const std::string& name, int size,
                                              bool method_may_follow) {
  if (slot.is_none()) return std::nullopt;
  if (PyIndex_Check(slot.ptr()) && !py::isinstance<py::array>(slot)) {
    ThrowArgument(name,
                  "is an output but got the integer " + std::string(py::str(slot)) +
                      (method_may_follow ? " — the method passed positionally lands here, and "
                                           "OpenCV 4.6 then silently uses its default method "
                                           "(opencv#27625)"
                                         : ""),
                  "pass the method by keyword: method=...");
  }
  if (!py::isinstance<py::array>(slot)) {
    ThrowArgument(name,
                  "is an output but got a " +
                      std::string(py::str(py::type::handle_of(slot).attr("__name__"))),
                  "leave it out (the result is returned), or pass a NumPy array to fill");
  }
  py::array array = py::reinterpret_borrow<py::array>(slot);
  if (array.dtype().is(py::dtype::of<double>()) && array.size() == size && array.writeable() &&
      (array.flags() & py::array::c_style)) {
    return py::reinterpret_borrow<py::array_t<double>>(slot);
  }
  return std::nullopt;  // OpenCV reallocates an output it cannot use: a new array is returned
}

py::array_t<double> Output(const Eigen::Ref<const Eigen::MatrixXd>& value,
                           std::optional<py::array_t<double>> slot) {
  py::array_t<double> out = slot ? *slot : py::array_t<double>({value.rows(), value.cols()});
  double* p = out.mutable_data();
  for (Eigen::Index r = 0; r < value.rows(); ++r)
    for (Eigen::Index c = 0; c < value.cols(); ++c) *p++ = value(r, c);
  return out;
}

constexpr const char* kHandEyeDoc =
    R"doc(calibrateHandEye(R_gripper2base, t_gripper2base, R_target2cam, t_target2cam[, R_cam2gripper[, t_cam2gripper[, method]]]) -> R_cam2gripper, t_cam2gripper

OpenCV 4.6's cv2.calibrateHandEye, solved by hecal (docs/python.md#the-opencv-drop-in).

Frames (eye-in-hand): R/t_gripper2base is T_base_gripper (the robot's pose), R/t_target2cam
is T_camera_target (the target seen by the camera), one per station; the result
R/t_cam2gripper is X = T_gripper_camera. Eye-to-hand: pass base2gripper (T_gripper_base) as
OpenCV documents; the result is then T_base_camera.
Inputs: lists of 3x3 rotation matrices or Rodrigues vectors ((3,), (3,1), (1,3)), or an Nx3x3
array; translations (3,), (3,1), (1,3) each or an Nx3 array; float32 or float64. Any length
unit (the result is in the same one); radians.
method: CALIB_HAND_EYE_ML (default, hecal's maximum likelihood), CALIB_HAND_EYE_TSAI,
_PARK, _HORAUD, _ANDREFF, _DANIILIDIS (OpenCV's values 0-4, hecal's implementations).
Pass it by keyword: a method passed positionally lands in R_cam2gripper (an output) and is
refused. No outlier rejection, covariance or convention check (hecal.calibrate has them).
Returns (R_cam2gripper 3x3, t_cam2gripper 3x1), float64.
Raises hecal.InputError (a ValueError) for an unknown method, fewer than 3 poses, lists of
different lengths, NaN/inf, a matrix that is not a rotation, a wrong shape;
hecal.DegenerateError when the data do not determine X (e.g. parallel rotation axes).)doc";

constexpr const char* kRobotWorldDoc =
    R"doc(calibrateRobotWorldHandEye(R_world2cam, t_world2cam, R_base2gripper, t_base2gripper[, R_base2world[, t_base2world[, R_gripper2cam[, t_gripper2cam[, method]]]]]) -> R_base2world, t_base2world, R_gripper2cam, t_gripper2cam

OpenCV 4.6's cv2.calibrateRobotWorldHandEye, solved by hecal (docs/python.md#the-opencv-drop-in).

Frames: R/t_world2cam is T_camera_world (world = the target), R/t_base2gripper is
T_gripper_base, one per station. Results: R/t_base2world = T_world_base (hecal's Z⁻¹) and
R/t_gripper2cam = T_camera_gripper (hecal's X⁻¹), eye-in-hand.
Inputs as for calibrateHandEye. method: CALIB_HAND_EYE_ML (default), or
CALIB_ROBOT_WORLD_HAND_EYE_SHAH (0), CALIB_ROBOT_WORLD_HAND_EYE_LI (1); pass it by keyword.
Returns four float64 arrays (3x3, 3x1, 3x3, 3x1). Raises as calibrateHandEye.)doc";

}  // namespace

void RegisterDropIn(py::module_& m) {
  m.attr("CALIB_HAND_EYE_TSAI") = 0;
  m.attr("CALIB_HAND_EYE_PARK") = 1;
  m.attr("CALIB_HAND_EYE_HORAUD") = 2;
  m.attr("CALIB_HAND_EYE_ANDREFF") = 3;
  m.attr("CALIB_HAND_EYE_DANIILIDIS") = 4;
  m.attr("CALIB_HAND_EYE_ML") = jobs::kDropInMl;
  m.attr("CALIB_ROBOT_WORLD_HAND_EYE_SHAH") = 0;
  m.attr("CALIB_ROBOT_WORLD_HAND_EYE_LI") = 1;

  m.def(
      "calibrateHandEye",
      [](py::handle R_gripper2base, py::handle t_gripper2base, py::handle R_target2cam,
         py::handle t_target2cam, py::handle R_cam2gripper, py::handle t_cam2gripper,
         py::handle method) {
        auto R_slot = OutputSlot(R_cam2gripper, "R_cam2gripper", 9, true);
        auto t_slot = OutputSlot(t_cam2gripper, "t_cam2gripper", 3, true);
        jobs::DropInCalibrateOptions options;
        options.method = ParseMethod(method, "calibrateHandEye");
        const jobs::DropInPoses robot = ParsePoses(R_gripper2base, t_gripper2base, "gripper2base");
        const jobs::DropInPoses camera = ParsePoses(R_target2cam, t_target2cam, "target2cam");
        jobs::DropInTransform X;
        {
          py::gil_scoped_release release;
          X = jobs::CalibrateHandEyeDropIn(robot, camera, options);
        }
        return py::make_tuple(Output(X.R, std::move(R_slot)), Output(X.t, std::move(t_slot)));
      },
      py::arg("R_gripper2base"), py::arg("t_gripper2base"), py::arg("R_target2cam"),
      py::arg("t_target2cam"), py::arg("R_cam2gripper") = py::none(),
      py::arg("t_cam2gripper") = py::none(), py::arg("method") = jobs::kDropInMl, kHandEyeDoc);

  m.def(
      "calibrateRobotWorldHandEye",
      [](py::handle R_world2cam, py::handle t_world2cam, py::handle R_base2gripper,
         py::handle t_base2gripper, py::handle R_base2world, py::handle t_base2world,
         py::handle R_gripper2cam, py::handle t_gripper2cam, py::handle method) {
        auto R_bw = OutputSlot(R_base2world, "R_base2world", 9, true);
        auto t_bw = OutputSlot(t_base2world, "t_base2world", 3, true);
        auto R_gc = OutputSlot(R_gripper2cam, "R_gripper2cam", 9, true);
        auto t_gc = OutputSlot(t_gripper2cam, "t_gripper2cam", 3, true);
        jobs::DropInCalibrateOptions options;
        options.method = ParseMethod(method, "calibrateRobotWorldHandEye");
        const jobs::DropInPoses camera = ParsePoses(R_world2cam, t_world2cam, "world2cam");
        const jobs::DropInPoses robot = ParsePoses(R_base2gripper, t_base2gripper, "base2gripper");
        jobs::RobotWorldDropIn result;
        {
          py::gil_scoped_release release;
          result = jobs::CalibrateRobotWorldHandEyeDropIn(camera, robot, options);
        }
        return py::make_tuple(Output(result.base2world.R, std::move(R_bw)),
                              Output(result.base2world.t, std::move(t_bw)),
                              Output(result.gripper2cam.R, std::move(R_gc)),
                              Output(result.gripper2cam.t, std::move(t_gc)));
      },
      py::arg("R_world2cam"), py::arg("t_world2cam"), py::arg("R_base2gripper"),
      py::arg("t_base2gripper"), py::arg("R_base2world") = py::none(),
      py::arg("t_base2world") = py::none(), py::arg("R_gripper2cam") = py::none(),
      py::arg("t_gripper2cam") = py::none(), py::arg("method") = jobs::kDropInMl, kRobotWorldDoc);
}

}  // namespace hecal::python
