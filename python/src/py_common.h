// Shared pieces of the Python bindings (python/src): names of enum values, numpy conversions, and
// the registration function of each part of the module.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "shadowvol/capture_choice.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/error.h"
#include "shadowvol/scene.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol::python {

namespace py = pybind11;

/// A scene as Python holds it: the scene and the warnings its loading produced.
struct PyScene {
  Scene scene;
  std::vector<std::string> warnings;
};

/// A JSON value as the Python object json.loads would give (dict, list, str, int, float, bool, None).
py::object toPython(const nlohmann::json& j);

/// 4 x 4 numpy array, a[row, column] = m[column][row] (GLM stores columns).
py::array_t<double> matrixToNumpy(const glm::dmat4& m);
/// The inverse; throws InputError naming `what` unless `a` is a 4 x 4 array.
glm::dmat4 matrixFromNumpy(const py::object& value, const std::string& what);

/// `value` as a numpy array of real numbers (float or integer dtype; any array-like is converted
/// first); InputError (`source`, `field`, the dtype) for complex, boolean, string or object arrays,
/// which a conversion to float would take without a word (a complex one losing its imaginary part).
py::array realArrayArg(const py::object& value, const std::string& source, const std::string& field,
                       const std::string& what);

/// The enum value named `text`; throws InputError naming the keyword argument and listing the choices.
/// "auto" (chooseCapture, capture_choice.h) needs the scene the map is captured from and what the
/// map is for.
CaptureMode captureModeArg(const std::string& text, const Scene* scene = nullptr,
                           CaptureUse use = CaptureUse::ShadowMap);

/// A light depth map's side N as the command line takes it (kMinVolumeMapSide .. kMaxWindowSide);
/// InputError naming `what` otherwise.
void checkResolutionArg(int resolution, const std::string& what);

/// The builder's options from the keyword arguments of build_volume and validate (names as there);
/// InputError names the argument.
/// A volume option's refusal (checkUserVolumeOptions: source "volume options") or a frame option's
/// (source "RenderOptions") named by this module's keyword, and the fields its problem names
/// (error.h's ${field} marks) by theirs; other errors as they are.
InputError asPythonArgumentError(const InputError& e);

VolumeBuildOptions volumeOptionsArg(const std::string& triangulation, bool blur, double blurOffset,
                                    std::optional<double> bias, const std::string& cap, bool flattenCap, int refine,
                                    bool chordPoints, int refineGrid = 1, bool refineGridEverywhere = false,
                                    bool hiddenSearch = true, bool facePrisms = false);

/// Makes `Cls.__new__(Cls)` raise TypeError naming `howToMake`: pybind11 would hand out an instance
/// whose C++ value was never constructed (a pickle stream of a bare NEWOBJ made one, and reading it
/// crashed). The module's own functions create instances without __new__.
void refuseBareInstances(py::handle cls, const std::string& howToMake);

/// An integer keyword argument (a map's size, refine steps, a sub-grid's S). Python's bool is a
/// subclass of int, which pybind11's int takes, and numpy's bool_ has __index__: refine=True built
/// a volume refined with one ray per edge. This type refuses both booleans, as it does float, with
/// the usual "incompatible function arguments" TypeError (the signature still reads int); numpy
/// integers are taken.
struct StrictInt {
  int value = 0;
  StrictInt(int v = 0) : value(v) {}  // NOLINT: defaults in py::arg(...) = 0
  operator int() const { return value; }
};

void registerScene(py::module_& m);
void registerDepth(py::module_& m);
void registerVolume(py::module_& m);
void registerValidate(py::module_& m);  ///< validate() and render(); GL builds only

}  // namespace shadowvol::python

namespace pybind11::detail {
template <>
struct type_caster<shadowvol::python::StrictInt> {
  PYBIND11_TYPE_CASTER(shadowvol::python::StrictInt, const_name("int"));
  bool load(handle src, bool /*convert*/) {
    if (!src || PyBool_Check(src.ptr())) return false;
    const std::string_view type = Py_TYPE(src.ptr())->tp_name;  // numpy.bool_ (numpy 1), numpy.bool (2)
    if (type == "numpy.bool_" || type == "numpy.bool") return false;
    type_caster<int> inner;
    if (!inner.load(src, false)) return false;  // an int or an object with __index__; never a float
    value = shadowvol::python::StrictInt(static_cast<int>(inner));
    return true;
  }
  static handle cast(shadowvol::python::StrictInt v, return_value_policy, handle) { return PyLong_FromLong(v.value); }
};
}  // namespace pybind11::detail
