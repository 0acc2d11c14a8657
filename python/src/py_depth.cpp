// Python: DepthMap (depths as a numpy array, light matrices), capture_depth(), load_depth(),
// DepthMap.from_array() and DepthMap.save().
#include <algorithm>
#include <cmath>
#include <limits>

#include <pybind11/eval.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "py_common.h"
#include "shadowvol/depth_map_io.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/error.h"
#ifdef SHADOWVOL_WITH_GL
#include "shadowvol/gl/renderer.h"
#endif

namespace shadowvol::python {
namespace {

DepthMap captureDepth(const PyScene& s, StrictInt width, StrictInt height, const std::string& capture,
                      const std::string& device, const std::string& platform, StrictInt refine, StrictInt guard) {
  // The map of a volume with `refine` steps, as build_volume reads it: capture='auto' chooses as
  // `shadowvol build --refine K` does (a fifteenth probe's finding: it chose for an unrefined volume).
  if (refine < 0 || refine > kMaxRefineSteps)  // as build_volume's refine
    throw InputError("python", "refine", std::to_string(refine),
                     "must be between 0 (unrefined) and " + std::to_string(kMaxRefineSteps));
  const CaptureMode mode = captureModeArg(capture, &s.scene, volumeUse(refine));
  checkResolutionArg(width, "width");  // at least 3, as the command line's: a smaller map's volume is empty
  checkResolutionArg(height, "height");
  checkDepthMapSize(width, height, "python", "width, height", DepthMapUse::MapOnly);  // as `shadowvol depth`
  checkGuardTexels(guard, "python", "guard");  // as `shadowvol depth --guard`
  checkGuardedDepthMapSize(width, height, guard, "python", "width, height", DepthMapUse::MapOnly);
  // As the command line's --platform: an EGL platform names how the GPU is reached.
  if (device == "cpu" && platform != "auto")
    throw InputError("python", "platform", platform, "picks the GPU's EGL platform: only with device='gpu'");
  if (s.scene.light.type == LightType::Point)
    throw InputError("python", "scene", "a point light",
                     "capture_depth and build_volume take one spot or directional light's map; a point light's six "
                     "cube faces are not available here (render and validate take point lights, as does the command "
                     "line's build)");
  py::gil_scoped_release release;
  if (device == "cpu") return captureDepthEmbree(s.scene, width, height, mode, guard);
  if (device != "gpu") throw InputError("python", "device", device, "expected cpu or gpu");
#ifdef SHADOWVOL_WITH_GL
  gl::RendererOptions ro;
  ro.context.platform = platform;
  try {
    gl::Renderer renderer(ro);
    renderer.setScene(s.scene);
    return renderer.captureDepth(width, height, mode, guard);
  } catch (const InputError& e) {  // the context's options (platform) by this module's keywords
    throw asPythonArgumentError(e);
  }
#else
  throw InputError("python", "device", device, "this shadowvol was built without GL (SHADOWVOL_BUILD_GL=OFF)");
#endif
}

// A finite depth beyond single precision would become +inf, "no hit", without a word (a fifteenth
// probe's 1e39 emptied a volume): refused, naming the texel (column, row) and the value. Asked of
// numpy in the array's own type, so a long double beyond double's range is found too.
void refuseBeyondFloat(const py::array& depth) {
  const py::module_ np = py::module_::import("numpy");
  const py::object beyond =
      np.attr("logical_and")(np.attr("isfinite")(depth), np.attr("greater")(np.attr("abs")(depth), std::numeric_limits<float>::max()));
  const auto at = np.attr("argwhere")(beyond).cast<py::array_t<py::ssize_t>>();
  if (at.shape(0) == 0) return;
  const py::ssize_t row = at.at(0, 0), column = at.at(0, 1);
  throw InputError("DepthMap.from_array", "texel " + std::to_string(column) + "," + std::to_string(row),
                   std::string(py::str(depth.attr("__getitem__")(py::make_tuple(row, column)))),
                   "beyond single precision (depths are stored as float32): give +inf for no hit");
}

DepthMap fromArray(const py::array& raw, const py::object& lightView, const py::object& lightProjection,
                   double nearPlane, double farPlane, const std::string& light, const std::string& capture,
                   const std::array<double, 3>& origin, StrictInt guard) {
  // Real numbers only: a complex array would lose its imaginary part without a word (a probe's finding).
  realArrayArg(raw, "DepthMap.from_array", "depth", "float or integer depths");
  if (raw.ndim() != 2)
    throw InputError("DepthMap.from_array", "depth", std::to_string(raw.ndim()) + "-dimensional array",
                     "expected a 2-dimensional array (rows x columns, row 0 at the bottom)");
  if (raw.shape(0) > kMaxDepthMapSide || raw.shape(1) > kMaxDepthMapSide)  // named as given, not clamped
    throw InputError("DepthMap.from_array", "depth",
                     std::to_string(raw.shape(0)) + " rows x " + std::to_string(raw.shape(1)) + " columns",
                     "a side is larger than " + std::to_string(kMaxDepthMapSide) + " texels");
  if (raw.shape(0) < 2 || raw.shape(1) < 2)  // named as given: rows x columns
    throw InputError("DepthMap.from_array", "depth",
                     std::to_string(raw.shape(0)) + " rows x " + std::to_string(raw.shape(1)) + " columns",
                     "a depth map needs at least 2 x 2 texels");
  if (raw.dtype().kind() == 'f' && raw.itemsize() > 4) refuseBeyondFloat(raw);
  const auto depth = raw.cast<py::array_t<float, py::array::forcecast>>();
  DepthMap map;
  map.height = int(depth.shape(0));
  map.width = int(depth.shape(1));
  checkDepthMapSize(map.width, map.height, "DepthMap.from_array", "depth");
  if (!parseLightType(light, map.lightType) || map.lightType == LightType::Point)  // a map is one light view
    throw InputError("DepthMap.from_array", "light", light, "expected spot or directional");
  map.capture = captureModeArg(capture);
  map.lightView = matrixFromNumpy(lightView, "light_view");
  map.lightProjection =
      matrixFromNumpy(lightProjection, "light_projection");
  map.nearPlane = nearPlane;
  map.farPlane = farPlane;
  map.origin = {origin[0], origin[1], origin[2]};  // checked below as a side file's /origin is
  checkDepthMapGuard(guard, map.width, map.height, "DepthMap.from_array", "guard");  // as a side file's /guard
  map.guard = guard;
  map.depth.resize(std::size_t(map.width) * std::size_t(map.height));
  auto r = depth.unchecked<2>();
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) map.depth[map.index(i, j)] = r(j, i);
  checkDepthValues(map, "DepthMap.from_array");
  static constexpr DepthMapFieldNames kKeywords{"depth", "near", "far", "light_view", "light_projection", "light",
                                                 "origin"};
  checkDepthMapLight(map, "DepthMap.from_array", kKeywords);
  return map;
}

// A DepthMap's pickle: from_array's arguments.
py::tuple depthMapState(const DepthMap& d) {
  py::array_t<float> depth({py::ssize_t(d.height), py::ssize_t(d.width)});
  std::copy(d.depth.begin(), d.depth.end(), depth.mutable_data());
  return py::make_tuple(depth, matrixToNumpy(d.lightView), matrixToNumpy(d.lightProjection), d.nearPlane, d.farPlane,
                        toString(d.lightType), std::string(toString(d.capture)),
                        std::array<double, 3>{d.origin.x, d.origin.y, d.origin.z}, d.guard);
}

DepthMap depthMapFromState(const py::tuple& t) {
  // 8 items: a pickle from before the guard band was kept (guard 0).
  if (t.size() != 8 && t.size() != 9)
    throw InputError("DepthMap pickle", "state", std::to_string(t.size()) + " items", "expected 9 (a DepthMap's pickle)");
  return fromArray(t[0].cast<py::array>(), t[1], t[2], t[3].cast<double>(), t[4].cast<double>(),
                   t[5].cast<std::string>(), t[6].cast<std::string>(), t[7].cast<std::array<double, 3>>(),
                   t.size() == 9 ? t[8].cast<StrictInt>() : StrictInt{0});
}

/// The depths as a read-only H x W float32 view that keeps the DepthMap alive.
py::array depthView(const py::object& self) {
  const DepthMap& map = self.cast<const DepthMap&>();
  py::array_t<float> a({py::ssize_t(map.height), py::ssize_t(map.width)},
                       {py::ssize_t(map.width) * py::ssize_t(sizeof(float)), py::ssize_t(sizeof(float))},
                       map.depth.data(), self);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

}  // namespace

void registerDepth(py::module_& m) {
  py::class_<DepthMap>(m, "DepthMap",
                       "A light's depth map: light-view depths (world units; inf = the light saw nothing) and the "
                       "light's matrices. Texel (i, j) is depth[j, i], row 0 at the bottom (OpenGL's order): use "
                       "numpy.flipud for an image.")
      .def_property_readonly("width", [](const DepthMap& d) { return d.width; })
      .def_property_readonly("height", [](const DepthMap& d) { return d.height; })
      .def_property_readonly("depth", &depthView, "read-only float32 array, shape (height, width)")
      .def_property_readonly("light", [](const DepthMap& d) { return toString(d.lightType); })
      .def_property_readonly("capture", [](const DepthMap& d) { return std::string(toString(d.capture)); })
      .def_property_readonly("light_view", [](const DepthMap& d) { return matrixToNumpy(d.lightView); },
                             "world -> light view, 4 x 4 (a[row, column])")
      .def_property_readonly("light_projection", [](const DepthMap& d) { return matrixToNumpy(d.lightProjection); },
                             "light view -> light clip, 4 x 4 (a[row, column])")
      .def_property_readonly("near", [](const DepthMap& d) { return d.nearPlane; })
      .def_property_readonly("far", [](const DepthMap& d) { return d.farPlane; })
      .def_property_readonly("origin", [](const DepthMap& d) { return py::make_tuple(d.origin.x, d.origin.y, d.origin.z); },
                             "world = the coordinates the matrices use + origin")
      .def_property_readonly("guard", [](const DepthMap& d) { return d.guard; },
                             "texels of the guard band on every side (capture_depth's guard): the light's window is "
                             "the inner (width - 2 guard) x (height - 2 guard) texels")
      .def_property_readonly("hit_count", &DepthMap::hitCount, "texels where the light saw a surface")
      .def_static("from_array", &fromArray, py::arg("depth"), py::arg("light_view"), py::arg("light_projection"),
                  py::arg("near"), py::arg("far"), py::arg("light") = "spot", py::arg("capture") = "back",
                  py::arg("origin") = std::array<double, 3>{0.0, 0.0, 0.0}, py::arg("guard") = 0,
                  "A depth map from a numpy array (rows x columns, row 0 at the bottom, inf = no hit) and the "
                  "light's matrices, checked as a depth file's side file is (docs: rigid view, a projection of "
                  "the light's kind mapping near and far to NDC z -1 and +1).")
      .def(
          "save",
          [](const DepthMap& d, const std::filesystem::path& path) {
            checkDepthMapPath(path, "DepthMap.save", "path");  // as `shadowvol depth --out`
            py::gil_scoped_release release;
            writeDepthMap(d, path);
          },
          py::arg("path"), "Writes a PFM plus its JSON side file (path + '.json'), as `shadowvol depth` does.")
      .def("__copy__", [](const DepthMap& d) { return DepthMap(d); })
      .def("__deepcopy__", [](const DepthMap& d, const py::dict&) { return DepthMap(d); }, py::arg("memo"))
      .def(
          "__reduce__",
          [](const py::object& self) {  // every protocol: (from-state function, (state,)), checked on loading
            return py::make_tuple(py::module_::import("shadowvol").attr("_depth_map_from_state"),
                                  py::make_tuple(depthMapState(self.cast<const DepthMap&>())));
          })
      .def("__repr__", [](const DepthMap& d) {
        return "<shadowvol.DepthMap " + std::to_string(d.width) + "x" + std::to_string(d.height) + " " +
               toString(d.lightType) + ", " + toString(d.capture) + ", " +
               std::to_string(d.hitCount()) + " texels hit>";
      });

  m.attr("DepthMap").attr("_from_state") = py::cpp_function(&depthMapFromState, py::arg("state"));
  // Pickle names its reconstructor by module and name: a Python function does (a pybind11 one is
  // bound to a capsule that pickle cannot name).
  py::exec(R"(
def _depth_map_from_state(state):
    """A DepthMap from the state its pickle holds (DepthMap.__reduce__), checked as from_array's arguments."""
    return DepthMap._from_state(state)
)",
           m.attr("__dict__"));
  refuseBareInstances(m.attr("DepthMap"), "DepthMap.from_array, capture_depth or load_depth");

  m.def("capture_depth", &captureDepth, py::arg("scene"), py::arg("width") = 256, py::arg("height") = 256,
        py::arg("capture") = "auto", py::arg("device") = "cpu", py::arg("platform") = "auto", py::arg("refine") = 0,
        py::arg("guard") = kVolumeGuardTexels,
        "The light's depth map of a scene: device='cpu' casts one Embree ray per texel centre, 'gpu' renders the "
        "light pass through EGL + OpenGL and reads it back (same texels hit, depths within 1e-4 relative). "
        "capture: auto (back when every mesh object is closed, else front: `--capture auto`), back (first surface "
        "facing away from the light), front, midpoint or entry (front capture's surface where a back face lies "
        "behind it). refine: the bisection steps of the volume the map is for (build_volume's refine): capture='auto' "
        "chooses for it as `shadowvol build --refine K` does (entry capture for a refined volume on closed meshes); "
        "0, the default, an unrefined volume's choice. guard: texels the map reaches past the light's window on every "
        "side (the map is width + 2 guard by height + 2 guard, the window's texels kept), so a volume built from it puts "
        "the map's outermost ring, on the far plane, outside the window: a shadow crossing the window's edge is not lit "
        "along it. The default is what `shadowvol depth` and the renderer use; 0: the window's texels alone.");
  m.def(
      "load_depth",
      [](const std::filesystem::path& path) {
        py::gil_scoped_release release;
        return readDepthMap(path);
      },
      py::arg("path"), "Reads a PFM depth map and its side file (as written by `shadowvol depth` or DepthMap.save).");
}

}  // namespace shadowvol::python
