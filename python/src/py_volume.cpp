// Python: build_volume(depth, ...) -> (V, F, stats) and export(V, F, path).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "py_common.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/report_json.h"
#include "shadowvol/volume_builder.h"

namespace shadowvol::python {

VolumeBuildOptions volumeOptionsArg(const std::string& triangulation, bool blur, double blurOffset,
                                 std::optional<double> bias, const std::string& cap, bool flattenCap, int refine,
                                 bool chordPoints, int refineGrid, bool refineGridEverywhere, bool hiddenSearch,
                                 bool facePrisms) {
  VolumeBuildOptions o;
  if (!parseTriangulation(triangulation, o.triangulation))
    throw InputError("python", "triangulation", triangulation, "expected " + choicesText(namesIn(kTriangulationNames)));
  if (!parseFarCap(cap, o.cap)) throw InputError("python", "cap", cap, "expected " + choicesText(namesIn(kFarCapNames)));
  o.blur = blur;
  o.blurOffset = blurOffset;
  o.bias = bias;
  o.flattenCap = flattenCap;
  o.refineSteps = refine;
  o.refineChords = chordPoints;
  o.refineSubdivisions = refineGrid;
  o.refineGridEverywhere = refineGridEverywhere;
  o.refineHidden = hiddenSearch;
  o.facePrisms = facePrisms;
  try {
    checkUserVolumeOptions(o);  // the command line's rules (a probe found them missing here)
  } catch (const InputError& e) {
    throw asPythonArgumentError(e);
  }
  return o;
}

namespace {

// The library's option fields as this module's keywords (a fifteenth probe's finding: refine_grid=3
// was "refine subdivisions", blur_offset "needs blur (--blur)"): the field refused and those its
// problem names (${field} marks, error.h), for the volume options and the frame's RenderOptions.
struct PythonName {
  const char* source;
  const char* library;
  const char* keyword;
};
constexpr PythonName kFieldKeywords[] = {
    {"volume options", "blur offset", "blur_offset"},
    {"volume options", "bias", "bias"},
    {"volume options", "refine steps", "refine"},
    {"volume options", "cap", "cap"},
    {"volume options", "refine subdivisions", "refine_grid"},
    {"volume options", "refine chords", "chord_points"},
    {"volume options", "refine grid everywhere", "refine_grid_everywhere"},
    {"volume options", "refine hidden", "hidden_search"},
    {"volume options", "face prisms", "face_prisms"},
    {"volume options", "flatten cap", "flatten_cap"},
    {"volume options", "blur", "blur"},
    {"RenderOptions", "refineCrossings", "crossings"},
    {"RenderOptions", "volume", "volume"},
    {"RenderOptions", "volumeCount", "count"},
    {"RenderOptions", "depthWidth", "resolution"},
    {"RenderOptions", "depthWidth x depthHeight", "resolution"},
    {"RenderOptions", "imageWidth x imageHeight", "size"},
    {"RenderOptions", "method", "method"},
    {"RenderOptions", "capture", "capture"},
    {"RenderOptions", "volumeOptions.cap", "cap"},
    {"RenderOptions", "volumeOptions.refineSteps", "refine"},
    {"RenderOptions", "volumeOptions.blurOffset", "blur_offset"},
    {"RenderOptions", "volumeOptions.bias", "bias"},
    {"ContextOptions", "platform", "platform"}};

// The keyword of `field` of `source`'s options, or null where this module has none.
const char* keywordOf(std::string_view source, std::string_view field) {
  for (const PythonName& n : kFieldKeywords)
    if (source == n.source && field == n.library) return n.keyword;
  return nullptr;
}

}  // namespace

InputError asPythonArgumentError(const InputError& e) {
  const std::string source = e.source();
  const char* keyword = keywordOf(source, e.field());
  if (!keyword && !e.hasFieldMarks()) return e;
  const std::string problem = e.problemNamed([&](std::string_view field) {
    const char* k = keywordOf(source, field);
    return std::string(k ? k : field);
  });
  return keyword ? InputError("python", keyword, e.value(), problem) : InputError(source, e.field(), e.value(), problem);
}

namespace {

// Refuses a map that `scene`'s geometry does not give back: the refinement casts its rays into the
// scene along the map's own light rays, so a map captured from another scene (a probe passed one
// without a word) would be refined against surfaces it does not show. Up to 16 x 16 texel centres
// are asked of the oracle; among those where the map or the rays hit something, at least 90 % must
// agree, or fewer than 4 disagree (a small object gives few samples; a wrong scene between them
// passes unseen: this is a guard against a mix-up, not a proof) (both hit, within 1e-3 of the map's near-far range: a GPU capture and the rays differ at a
// few silhouette texels and by about 1e-4 in depth, README's `depth` command).
void checkMapFromScene(const DepthMap& depth, const DepthOracle& oracle) {
  std::vector<glm::dvec2> ndc;
  std::vector<float> stored;
  const int stepI = std::max(1, depth.width / 16), stepJ = std::max(1, depth.height / 16);
  for (int j = stepJ / 2; j < depth.height; j += stepJ)
    for (int i = stepI / 2; i < depth.width; i += stepI) {
      ndc.push_back(depth.texelNdc(double(i), double(j)));
      stored.push_back(depth.at(i, j));
    }
  std::vector<float> traced(ndc.size());
  oracle(depth, ndc, traced);
  const double tolerance = 1e-3 * (depth.farPlane - depth.nearPlane);
  std::size_t judged = 0, agree = 0;
  for (std::size_t k = 0; k < ndc.size(); ++k) {
    const bool mapHit = stored[k] != DepthMap::kNoHit, rayHit = traced[k] != DepthMap::kNoHit;
    if (!mapHit && !rayHit) continue;
    ++judged;
    if (mapHit && rayHit && std::abs(double(stored[k]) - double(traced[k])) <= tolerance) ++agree;
  }
  // A few silhouette texels may differ (GPU against rays): refused only when several disagree.
  if (judged - agree >= 4 && double(agree) < 0.9 * double(judged))
    throw InputError("python", "scene", std::to_string(agree) + " of " + std::to_string(judged) + " texels sampled",
                     "the scene's surfaces do not give back the depth map (at least 90 % of the sampled texels "
                     "that hit must agree): refine needs the scene the map was captured from");
}

py::tuple buildVolumeArrays(const DepthMap& depth, const std::string& triangulation, bool blur, double blurOffset,
                            std::optional<double> bias, const std::string& cap, bool flattenCap, StrictInt refine,
                            const PyScene* scene, bool chordPoints, StrictInt refineGrid, bool refineGridEverywhere,
                            bool hiddenSearch, bool facePrisms) {
  VolumeBuildOptions o = volumeOptionsArg(triangulation, blur, blurOffset, bias, cap, flattenCap, refine, chordPoints,
                                          refineGrid, refineGridEverywhere, hiddenSearch, facePrisms);
  if (refine > 0 && !scene)
    throw InputError("python", "refine", std::to_string(refine),
                     "needs scene=: the refinement casts rays into the scene the depth map was captured from");
  if (refine == 0 && scene)  // as the command line refuses an option that changes nothing
    throw InputError("python", "scene", "given", "is read only by the refinement: give refine=K too, or leave out scene=");
  if (depth.width < kMinVolumeMapSide || depth.height < kMinVolumeMapSide)  // as `build --depth` refuses it
    throw InputError("python", "depth", std::to_string(depth.width) + "x" + std::to_string(depth.height),
                     "a volume needs a map of at least " + std::to_string(kMinVolumeMapSide) + " x " +
                         std::to_string(kMinVolumeMapSide) + " texels: the outermost ring lies on the far plane");
  VolumeBuildResult r;
  {
    py::gil_scoped_release release;
    std::unique_ptr<EmbreeDepthOracle> oracle;
    if (refine > 0) {
      oracle = std::make_unique<EmbreeDepthOracle>(scene->scene);
      o.depthOracle = oracle->oracle();
      o.surfaceEnds = oracle->surfaceEnds();  // the snap, as the command line (crossing_snap.h)
      o.nearerSurfaces = oracle->nearerSurfaces();  // the sub-grid's search for hidden surfaces
      o.casterFaces = oracle->casterFaces();        // the face prisms' faces
      o.withoutCasters = oracle->withoutCasters();  // the sheet hands their columns over
      checkMapFromScene(depth, o.depthOracle);
    }
    try {
      r = buildVolume(depth, o);
    } catch (const InputError& e) {  // the options against the map (a bias beyond its depth range), by keyword
      throw asPythonArgumentError(e);
    }
  }
  if (r.mesh.vertexCount() > std::size_t(INT32_MAX))
    throw InputError("python", "depth", std::to_string(r.mesh.vertexCount()) + " vertices",
                     "more than int32 indices can address");
  py::array_t<double> v({py::ssize_t(r.mesh.vertexCount()), py::ssize_t(3)});
  py::array_t<std::int32_t> f({py::ssize_t(r.mesh.triangleCount()), py::ssize_t(3)});
  auto vr = v.mutable_unchecked<2>();
  auto fr = f.mutable_unchecked<2>();
  for (std::size_t k = 0; k < r.mesh.vertexCount(); ++k)
    for (int c = 0; c < 3; ++c) vr(k, c) = r.mesh.positions[k][c] + r.mesh.origin[c];
  for (std::size_t k = 0; k < r.mesh.triangleCount(); ++k)
    for (int c = 0; c < 3; ++c) fr(k, c) = std::int32_t(r.mesh.triangles[k][c]);
  nlohmann::json stats = describeVolumeStats(r.stats);
  stats["partStarts"] = r.mesh.partStarts;  // F's rows where a closed part after the first begins (face prisms)
  return py::make_tuple(v, f, toPython(stats));
}

/// V (N x 3, finite) and F (M x 3, indices in [0, N)) as a VolumeMesh; InputError names the array,
/// the row and the value.
VolumeMesh meshFromArrays(const py::array_t<double, py::array::forcecast>& v,
                          const py::array_t<std::int64_t, py::array::forcecast>& f) {
  if (v.ndim() != 2 || v.shape(1) != 3) throw InputError("export", "V", "", "expected an N x 3 array of positions");
  if (f.ndim() != 2 || f.shape(1) != 3) throw InputError("export", "F", "", "expected an M x 3 array of vertex indices");
  VolumeMesh mesh;
  auto vr = v.unchecked<2>();
  auto fr = f.unchecked<2>();
  mesh.positions.resize(std::size_t(v.shape(0)));
  for (py::ssize_t k = 0; k < v.shape(0); ++k) {
    mesh.positions[std::size_t(k)] = {vr(k, 0), vr(k, 1), vr(k, 2)};
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(vr(k, c)))
        throw InputError("export", "V[" + std::to_string(k) + "]", std::to_string(vr(k, c)), "positions must be finite");
  }
  mesh.triangles.resize(std::size_t(f.shape(0)));
  for (py::ssize_t k = 0; k < f.shape(0); ++k)
    for (int c = 0; c < 3; ++c) {
      const std::int64_t idx = fr(k, c);
      if (idx < 0 || idx >= v.shape(0))
        throw InputError("export", "F[" + std::to_string(k) + "]", std::to_string(idx),
                         "index out of range (V has " + std::to_string(v.shape(0)) + " rows)");
      mesh.triangles[std::size_t(k)][c] = std::uint32_t(idx);
    }
  return mesh;
}

}  // namespace

void registerVolume(py::module_& m) {
  m.def("build_volume", &buildVolumeArrays, py::arg("depth"), py::kw_only(), py::arg("triangulation") = "perfect",
        py::arg("blur").noconvert() = false, py::arg("blur_offset") = 0.0, py::arg("bias") = py::none(), py::arg("cap") = "exact",
        py::arg("flatten_cap").noconvert() = true, py::arg("refine") = 0, py::arg("scene") = nullptr,
        py::arg("chord_points").noconvert() = false, py::arg("refine_grid") = 1, py::arg("refine_grid_everywhere").noconvert() = false,
        py::arg("hidden_search").noconvert() = true, py::arg("face_prisms").noconvert() = false,
        "The shadow volume of a depth map: (V, F, stats) with V float64 N x 3 (world units), F int32 M x 3 "
        "(counter-clockwise seen from outside) and stats a dict of counts and times (milliseconds). With the exact "
        "cap (default) the mesh is closed, outward and welded (docs/volume.md). refine=K (1..16) places each wall "
        "within 2^-(K+1) texel of the silhouette by K rays per boundary edge into `scene` (the scene the map was "
        "captured from); refine_grid=S (2, 4, 8) refines the quads with a boundary edge whose straight wall misses "
        "the sub-grid's samples on an S x S sub-grid, every such quad with refine_grid_everywhere=True "
        "(docs/volume.md, \"Sub-grid\"), and the quads whose square hides a surface between the texel centres "
        "(found from the scene's triangles; hidden_search=False: not; docs/volume.md, \"Hidden surfaces\"). "
        "face_prisms=True (with refine) adds the prisms of the closed meshes' faces turned towards the light in the "
        "refined quads' columns (each region of such faces whole) as a second closed part, whose first row in F is "
        "stats['partStarts'][0], the sheet handing those columns over to them "
        "(docs/volume.md, \"Face prisms\"). bias=None: the default (0 for back capture).");
  m.def(
      "export",
      [](const py::object& positions, const py::array& f, const std::filesystem::path& path, bool doublePrecision) {
        if (path.empty()) throw InputError("export", "path", "\"\"", "a mesh file name is required");
        // Positions must be real numbers (any array-like, a list too): a complex array would lose its
        // imaginary part (numpy only warns), booleans and objects are no coordinates.
        const py::array v = realArrayArg(positions, "export", "V", "float or integer positions");
        // Indices must be integers: a float array would be truncated without a word.
        if (f.dtype().kind() != 'i' && f.dtype().kind() != 'u')
          throw InputError("export", "F", std::string(py::str(f.dtype())), "expected an integer array of vertex indices");
        if (f.dtype().kind() == 'u' && f.dtype().itemsize() == 8) {  // would wrap to negative as int64
          const auto u = f.cast<py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>>();
          const std::uint64_t* p = u.data();
          for (py::ssize_t k = 0; k < u.size(); ++k)
            if (p[k] > std::uint64_t(INT64_MAX))
              throw InputError("export", "F", std::to_string(p[k]), "a vertex index beyond any vertex array");
        }
        const VolumeMesh mesh = meshFromArrays(v.cast<py::array_t<double, py::array::forcecast>>(),
                                               f.cast<py::array_t<std::int64_t, py::array::forcecast>>());
        WrittenVolume written;
        {
          py::gil_scoped_release release;
          written = writeVolumeMesh(mesh, path, doublePrecision);  // float: relative to V's box where far out
        }
        std::string ext = path.extension().string();
        for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (written.collapsedTriangles > 0 &&
            PyErr_WarnEx(PyExc_RuntimeWarning,
                         (path.string() + ": " + std::to_string(written.collapsedTriangles) +
                          " triangles have two corners at one position as written (zero area in the file)" +
                          (doublePrecision || ext == ".stl" || ext == ".gltf" || ext == ".glb"
                               ? std::string()
                               : std::string(": double_precision=True writes doubles")))
                             .c_str(),
                         1) < 0)
          throw py::error_already_set();  // a warnings filter made it an error
        return py::make_tuple(written.origin.x, written.origin.y, written.origin.z);
      },
      py::arg("V"), py::arg("F"), py::arg("path"), py::kw_only(), py::arg("double_precision").noconvert() = false,
      "Writes a triangle mesh by the extension (case-insensitive): .ply (binary), .obj, .off, .stl, .gltf, .glb; "
      "atomically (a failure leaves no file). Coordinates are written as float32 unless double_precision=True "
      "(PLY doubles, OBJ/OFF 17 digits; glTF keeps float positions, its node's translation the origin; STL "
      "stores float only and refuses it). In float32, V lying so far from "
      "the world origin that float would keep fewer than about 2^20 steps across it is written relative to the "
      "centre of its box (as a scene's mesh file is read), named in the PLY and OBJ comment 'shadowvol origin X Y "
      "Z', STL's header and glTF's node translation (OFF has no place for it). Returns that origin, (0, 0, 0) "
      "when V is written as given: world = written + origin.");
}

}  // namespace shadowvol::python
