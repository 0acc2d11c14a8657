// Python: Scene, default_scene(), load_scene(path).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "py_common.h"
#include "shadowvol/report_json.h"

namespace shadowvol::python {
namespace {

/// All objects merged, world coordinates in double: (V float64 N x 3, F int32 M x 3).
py::tuple sceneMesh(const PyScene& s) {
  const TriangleMesh mesh = s.scene.merged();
  py::array_t<double> v({py::ssize_t(mesh.positions.size()), py::ssize_t(3)});
  py::array_t<std::int32_t> f({py::ssize_t(mesh.triangles.size()), py::ssize_t(3)});
  auto vr = v.mutable_unchecked<2>();
  auto fr = f.mutable_unchecked<2>();
  for (std::size_t k = 0; k < mesh.positions.size(); ++k)
    for (int c = 0; c < 3; ++c) vr(k, c) = double(mesh.positions[k][c]) + s.scene.origin[c];
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    for (int c = 0; c < 3; ++c) fr(k, c) = std::int32_t(mesh.triangles[k][c]);
  return py::make_tuple(v, f);
}

}  // namespace

void registerScene(py::module_& m) {
  py::class_<PyScene> cls(m, "Scene",
                      "A scene: world-space triangle meshes, one or more lights, one camera (README 'Scene files'). Positions "
                      "are kept relative to `origin` (rebased when the scene lies far from the world origin).");
  cls
      .def_property_readonly("source", [](const PyScene& s) { return s.scene.source; }, "file it was loaded from, or 'default'")
      .def("__copy__", [](const PyScene& s) { return PyScene(s); },
           "A copy (copy.copy, copy.deepcopy): keep one before fit_light_to_view changes the scene in place.")
      .def("__deepcopy__", [](const PyScene& s, const py::dict&) { return PyScene(s); }, py::arg("memo"))
      .def_property_readonly("triangle_count", [](const PyScene& s) { return s.scene.triangleCount(); })
      .def_property_readonly("object_names",
                             [](const PyScene& s) {
                               std::vector<std::string> names;
                               for (const auto& o : s.scene.objects) names.push_back(o.name);
                               return names;
                             })
      .def_property_readonly("origin", [](const PyScene& s) { return py::make_tuple(s.scene.origin.x, s.scene.origin.y, s.scene.origin.z); })
      .def_property_readonly("warnings", [](const PyScene& s) { return s.warnings; },
                             "what loading noticed (a light inside a closed mesh, a moved far plane)")
      .def("describe", [](const PyScene& s) { return toPython(describeScene(s.scene)); },
           "The scene as `shadowvol scene --json` prints it: counts, bounds, light and camera (world units).")
      .def(
          "fit_light_to_view",
          [](PyScene& s, StrictInt resolution) {
            checkResolutionArg(resolution, "resolution");
            const LightFitResult r = fitLightToView(s.scene, resolution);
            py::dict d;
            d["changed"] = r.changed;
            d["window_before"] = r.windowBefore;
            d["window_after"] = r.windowAfter;
            d["note"] = r.note;
            return d;
          },
          py::arg("resolution") = 256,
          "Narrows the light's frustum to the receivers the camera sees (`--fit view`), keeping 2 texels of a "
          "resolution x resolution map to spare; changes the scene in place. window_*: a spot light's opening "
          "(degrees) or a directional light's half extent.")
      .def(
          "receiver_texel_size",
          [](const PyScene& s, StrictInt resolution) {
            checkResolutionArg(resolution, "resolution");
            return receiverTexelSize(s.scene, resolution);
          },
          py::arg("resolution") = 256,
          "(smallest, largest) light texel footprint on the receivers the camera sees, world units; None if it sees "
          "none of the lit scene.")
      .def("mesh", &sceneMesh,
           "All objects merged: (V, F), V float64 N x 3 in world units, F int32 M x 3 counter-clockwise.")
      .def("__repr__", [](const PyScene& s) {
        return "<shadowvol.Scene '" + s.scene.source + "': " + std::to_string(s.scene.objects.size()) + " objects, " +
               std::to_string(s.scene.triangleCount()) + " triangles>";
      })
      .def("__reduce__", [](const PyScene&) -> py::object {
        // Every protocol asks here first (protocols 0 and 1 went on to a pybind11 base that aborted).
        throw py::type_error("cannot pickle a shadowvol.Scene: keep its file and load_scene it again, or "
                             "copy.deepcopy it within one process");
      });
  refuseBareInstances(cls, "load_scene or default_scene");

  m.def("default_scene", [] { return PyScene{defaultScene(), {}}; },
        "The built-in default scene: a sphere floating above a ground plane under a spot light.");
  m.def(
      "load_scene",
      [](const std::filesystem::path& path) {
        SceneLoadResult r;
        {
          py::gil_scoped_release release;
          r = loadScene(path);
        }
        return PyScene{std::move(r.scene), std::move(r.warnings)};
      },
      py::arg("path"),
      "Reads a JSON scene file (README 'Scene files'). Raises InputError naming the file, the field and the value.");
}

}  // namespace shadowvol::python
