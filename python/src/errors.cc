// Errors (docs/python.md#errors): hecal's two C++ errors as Python exceptions.
//   hecal.Error            — the base of both (an Exception).
//   hecal.InputError       — also a ValueError: a file, option or argument is wrong. str() is the
//                            C++ InputError's text (the CLI's words: "source:line: what (fix:
//                            how)"); attributes source, line (0 when not line-bound), problem, fix.
//   hecal.DegenerateError  — the data are well formed but do not determine the unknowns; str()
//                            names what cannot be observed, attribute unobservable.
// The classes are defined in Python (so InputError can derive from ValueError and carry
// attributes) and raised from the translator below.
#include <string>

#include <pybind11/eval.h>

#include "bindings.h"

namespace hecal::python {
namespace {

// Owned for the life of the process (the interpreter keeps the module alive; never released).
PyObject* input_error_type = nullptr;
PyObject* degenerate_error_type = nullptr;

constexpr const char* kErrorClasses = R"doc(
class Error(Exception):
    """Base of every error hecal raises."""


class InputError(Error, ValueError):
    """A file, option or argument is wrong.

    str(e) is the same line the command line prints: "source:line: what (fix: how)".
    Attributes: source (file name, or the argument / option that holds the bad value),
    line (1-based line in the file, 0 when not line-bound), problem (what is wrong),
    fix (how to fix it).
    """

    def __init__(self, message, source="", line=0, problem="", fix=""):
        super().__init__(message)
        self.source = source
        self.line = line
        self.problem = problem
        self.fix = fix


class DegenerateError(Error):
    """The data are well formed but do not determine the unknowns.

    str(e) names what cannot be observed (e.g. parallel rotation axes) and what data would
    make it observable; attribute unobservable.
    """

    def __init__(self, message, unobservable=""):
        super().__init__(message)
        self.unobservable = unobservable
)doc";

}  // namespace

void ThrowArgument(const std::string& argument, const std::string& problem,
                   const std::string& fix) {
  throw InputError(argument, 0, problem, fix);
}

void RegisterErrors(py::module_& m) {
  py::dict scope;
  scope["__builtins__"] = py::module_::import("builtins");
  scope["__name__"] = "hecal";
  py::exec(kErrorClasses, scope);
  for (const char* name : {"Error", "InputError", "DegenerateError"}) {
    py::object type = scope[name];
    type.attr("__module__") = "hecal";
    m.attr(name) = type;
  }
  input_error_type = py::object(scope["InputError"]).release().ptr();
  degenerate_error_type = py::object(scope["DegenerateError"]).release().ptr();
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const hecal::InputError& e) {
      py::object instance = py::reinterpret_borrow<py::object>(input_error_type)(
          e.what(), e.source(), e.line(), e.problem(), e.fix());
      PyErr_SetObject(input_error_type, instance.ptr());
    } catch (const hecal::DegenerateError& e) {
      py::object instance = py::reinterpret_borrow<py::object>(degenerate_error_type)(
          e.what(), e.unobservable());
      PyErr_SetObject(degenerate_error_type, instance.ptr());
    }
  });
}

}  // namespace hecal::python
