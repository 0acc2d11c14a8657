// The Python module `shadowvol` (pybind11): scenes, depth capture, volume building, export and
// validation, with the library's rules and messages. Library errors become Python exceptions with
// the same message: InputError -> shadowvol.InputError (a ValueError), GlError ->
// shadowvol.GlError (a RuntimeError), anything else -> RuntimeError.
#include <map>
#include <string>

#include "py_common.h"

#include "shadowvol/capture_choice.h"
#include "shadowvol/error.h"
#include "shadowvol/version.h"
#ifdef SHADOWVOL_WITH_GL
#include "shadowvol/gl/gl_error.h"
#endif

namespace shadowvol::python {

py::object toPython(const nlohmann::json& j) {
  // Not cached in a static: its destructor would run after the interpreter has finalized.
  return py::module_::import("json").attr("loads")(j.dump());
}

py::array_t<double> matrixToNumpy(const glm::dmat4& m) {
  py::array_t<double> a({4, 4});
  auto r = a.mutable_unchecked<2>();
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) r(row, col) = m[col][row];
  return a;
}

glm::dmat4 matrixFromNumpy(const py::object& value, const std::string& what) {
  // Real numbers in a 4 x 4 array, named as given (a fifteenth probe's: a 3 x 3 matrix was "a
  // 2-dimensional array", a complex one lost its imaginary part, strings raised numpy's error).
  const py::array raw = py::array::ensure(value);
  if (!raw) throw InputError("python", what, std::string(py::str(py::repr(value))).substr(0, 80), "expected a 4 x 4 array");
  const char kind = raw.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'O')  // objects: converted below if they are numbers
    throw InputError("python", what, std::string(py::str(raw.dtype())), "expected a 4 x 4 array of real numbers");
  std::string shape;
  for (py::ssize_t k = 0; k < raw.ndim(); ++k) shape += (k ? " x " : "") + std::to_string(raw.shape(k));
  if (raw.ndim() != 2 || raw.shape(0) != 4 || raw.shape(1) != 4)
    throw InputError("python", what, (shape.empty() ? "a scalar" : shape) + " array", "expected a 4 x 4 array");
  py::array_t<double> a;
  try {
    a = raw.cast<py::array_t<double, py::array::forcecast>>();
  } catch (const py::error_already_set&) {
    throw InputError("python", what, "an array of objects", "expected a 4 x 4 array of real numbers");
  } catch (const py::cast_error&) {
    throw InputError("python", what, "an array of objects", "expected a 4 x 4 array of real numbers");
  }
  glm::dmat4 m(1.0);
  auto r = a.unchecked<2>();
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) m[col][row] = r(row, col);
  return m;
}

CaptureMode captureModeArg(const std::string& text, const Scene* scene, CaptureUse use) {
  if (text == "auto") {
    if (!scene)
      throw InputError("python", "capture", text,
                       "auto chooses by the scene's meshes: give back, front, midpoint or entry");
    return chooseCapture(*scene, use).mode;
  }
  CaptureMode mode;
  if (!parseCaptureMode(text, mode))
    throw InputError("python", "capture", text, "expected " + choicesText(namesIn(kCaptureModeNames, scene ? std::initializer_list<const char*>{"auto"}
                                                                                    : std::initializer_list<const char*>{})));
  return mode;
}

py::array realArrayArg(const py::object& value, const std::string& source, const std::string& field,
                       const std::string& what) {
  const py::array a = py::array::ensure(value);
  if (!a) throw InputError(source, field, std::string(py::str(py::repr(value))).substr(0, 80), "expected an array of " + what);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw InputError(source, field, std::string(py::str(a.dtype())), "expected an array of real numbers (" + what + ")");
  return a;
}

void checkResolutionArg(int resolution, const std::string& what) {
  if (resolution < kMinVolumeMapSide || resolution > kMaxWindowSide)
    throw InputError("python", what, std::to_string(resolution),
                     "must be between " + std::to_string(kMinVolumeMapSide) + " and " + std::to_string(kMaxWindowSide));
}

namespace {

// The refusals by type (refuseBareInstances), for the C-level constructor slot below.
std::map<PyTypeObject*, std::string>& bareInstanceRefusals() {
  static std::map<PyTypeObject*, std::string> refusals;
  return refusals;
}

PyObject* refuseNew(PyTypeObject* type, PyObject*, PyObject*) {
  const auto& refusals = bareInstanceRefusals();
  PyTypeObject* t = type;  // a Python subclass inherits the refusal
  while (t && !refusals.count(t)) t = t->tp_base;
  PyErr_SetString(PyExc_TypeError, t ? refusals.at(t).c_str() : "this shadowvol type has no constructor");
  return nullptr;
}

}  // namespace

void refuseBareInstances(py::handle cls, const std::string& howToMake) {
  const std::string name = py::str(cls.attr("__name__"));
  const std::string text = "shadowvol." + name + " objects are made by " + howToMake + ", not by " + name + ".__new__";
  bareInstanceRefusals()[reinterpret_cast<PyTypeObject*>(cls.ptr())] = text;
  const py::cpp_function refuse([text](const py::args&, const py::kwargs&) -> py::object { throw py::type_error(text); });
  cls.attr("__new__") = py::reinterpret_steal<py::object>(PyStaticMethod_New(refuse.ptr()));
  // Setting __new__ made the type's constructor slot call it; a C slot of its own instead makes
  // Python refuse a base's __new__ on it too ("pybind11_object.__new__(DepthMap) is not safe"), as
  // a pickle stream naming DepthMap.__base__.__new__ did (a second reader's finding: its object
  // crashed when read). The module's functions make instances without __new__.
  auto* type = reinterpret_cast<PyTypeObject*>(cls.ptr());
  type->tp_new = refuseNew;
  PyType_Modified(type);
}

}  // namespace shadowvol::python

PYBIND11_MODULE(shadowvol, m) {
  namespace sp = shadowvol::python;
  m.doc() =
      "shadowvol: explicit shadow-volume meshes from light depth maps. default_scene / load_scene -> "
      "capture_depth -> build_volume -> export; validate renders a frame (EGL + OpenGL) and checks it by ray "
      "casting.";
  m.attr("__version__") = SHADOWVOL_VERSION;
  // InputError with its parts as attributes (source, field, value, problem), so a caller can tell
  // which argument or file field was refused without parsing the message (a fifteenth probe's).
  static pybind11::exception<shadowvol::InputError> inputError(m, "InputError", PyExc_ValueError);
  inputError.doc() = "Bad input (a ValueError): the message names the file or argument, field and value; the parts "
                     "are the attributes source, field, value and problem.";
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const shadowvol::InputError& e) {
      const auto type = pybind11::reinterpret_borrow<pybind11::object>(inputError.ptr());
      pybind11::object error = type(e.what());
      error.attr("source") = e.source();
      error.attr("field") = e.field();
      error.attr("value") = e.value();
      error.attr("problem") = e.problem();
      PyErr_SetObject(inputError.ptr(), error.ptr());
    }
  });
#ifdef SHADOWVOL_WITH_GL
  pybind11::register_exception<shadowvol::gl::GlError>(m, "GlError", PyExc_RuntimeError).doc() =
      "The GL driver failed or is missing (a RuntimeError): no EGL display, no context, a GL error.";
  m.attr("has_gl") = true;
#else
  m.attr("has_gl") = false;
#endif
  sp::registerScene(m);
  sp::registerDepth(m);
  sp::registerVolume(m);
  sp::registerValidate(m);
}
