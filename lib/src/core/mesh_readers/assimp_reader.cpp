#include "mesh_readers/assimp_reader.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include "mesh_readers/corner_welder.h"
#include "mesh_readers/isolated_call.h"
#include "mesh_readers/number_text.h"
#include "mesh_readers/own_formats.h"
#include "shadowvol/error.h"

namespace shadowvol::mesh_readers {
namespace {

// Positions only: everything else is removed before the other steps run, so that welding and
// triangulation see no normals, colours or texture coordinates.
constexpr unsigned kRemovedComponents = aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS |
                                        aiComponent_TEXCOORDS | aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS |
                                        aiComponent_TEXTURES | aiComponent_LIGHTS | aiComponent_CAMERAS |
                                        aiComponent_MATERIALS;
// The steps before the node check (checkNodes); collect then places each node's meshes by its
// transformation (in double, a mirror reversing the winding).
constexpr unsigned kSteps = aiProcess_RemoveComponent | aiProcess_Triangulate | aiProcess_SortByPType |
                            aiProcess_ValidateDataStructure;

// A node's transformation in double.
glm::dmat4 toDouble(const aiMatrix4x4& m) {
  glm::dmat4 d(1.0);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) d[c][r] = double(m[r][c]);
  return d;
}

// Refuses a node that places meshes by a transformation that is not finite or is singular
// (determinant 0, say a glTF matrix of zeros), accumulated from the root in double (a float
// determinant overflows at a uniform scale of 1e13): it would collapse them to a plane, a line or
// a point, or make their positions NaN. Named by the node's path.
void checkNodes(const aiNode& node, const glm::dmat4& parent, const std::string& path, const std::string& source) {
  const glm::dmat4 m = parent * toDouble(node.mTransformation);
  const std::string here = path + "/" + (node.mName.length > 0 ? std::string(node.mName.C_Str()) : "(unnamed)");
  if (node.mNumMeshes > 0) {
    bool finite = true;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(m[c][r]) && std::abs(m[c][r]) <= 3.4e38;
    const double det = finite ? glm::determinant(m) : 0.0;
    if (!finite || det == 0.0)
      throw InputError(source, "node " + here + " transformation", finite ? "determinant 0" : "not finite",
                       "it would collapse the node's meshes (a matrix of zeros, a scale of 0, or a NaN)");
    if (!std::isfinite(det))
      throw InputError(source, "node " + here + " transformation", "determinant " + numberText(det),
                       "its scale is too large to place the node's meshes in float coordinates");
  }
  for (unsigned k = 0; k < node.mNumChildren; ++k) checkNodes(*node.mChildren[k], m, here, source);
}

// Mesh m's triangles, its positions placed by `place` in double, into `mesh` (welded by their
// bits, in corner order, by `weld`; ParsedMesh::weldCorners welds them again once stored in float).
// A mirroring placement (negative determinant) reverses the winding, as glTF asks and as the scene
// file's own mirrors do, so that faces keep facing the side they faced in the mesh.
void collectMesh(const aiMesh& am, unsigned m, const glm::dmat4& place, const std::string& source,
                 CornerWelder<glm::dvec3>& weld, ParsedMesh& mesh) {
  std::vector<glm::dvec3> stored(am.mNumVertices), placed(am.mNumVertices);
  for (unsigned v = 0; v < am.mNumVertices; ++v) {
    const aiVector3D& p = am.mVertices[v];
    stored[v] = glm::dvec3(p.x, p.y, p.z);
    placed[v] = glm::dvec3(place * glm::dvec4(stored[v], 1.0));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
        !checkedPoint(placed[v].x, placed[v].y, placed[v].z))
      throw InputError(source, "mesh " + std::to_string(m) + " vertex " + std::to_string(v),
                       numberText(p.x) + " " + numberText(p.y) + " " + numberText(p.z),
                       "position is not finite (as stored, or as its node places it)");
  }
  mesh.floatPlacement = FloatPlacement::worse(mesh.floatPlacement, FloatPlacement::of(stored));
  const bool mirrored = glm::determinant(glm::dmat3(place)) < 0.0;
  for (unsigned f = 0; f < am.mNumFaces; ++f) {
    const aiFace& face = am.mFaces[f];
    if (face.mNumIndices != 3) continue;  // SortByPType removed points and lines; none are left
    std::array<std::uint32_t, 3> t{};
    for (int c = 0; c < 3; ++c) {
      const unsigned k = face.mIndices[c];
      if (k >= am.mNumVertices)
        throw InputError(source, "mesh " + std::to_string(m) + " face " + std::to_string(f), std::to_string(k),
                         "vertex index out of range");
      t[c] = weld.vertex(placed[k]);
    }
    if (mirrored) std::swap(t[1], t[2]);
    mesh.triangles.push_back(t);
  }
}

// Every mesh of `node` and its children, placed by their transformations accumulated in double.
void collectNode(const aiScene& scene, const aiNode& node, const glm::dmat4& parent, const std::string& source,
                 CornerWelder<glm::dvec3>& weld, ParsedMesh& mesh) {
  const glm::dmat4 place = parent * toDouble(node.mTransformation);
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const unsigned m = node.mMeshes[k];
    if (m < scene.mNumMeshes) collectMesh(*scene.mMeshes[m], m, place, source, weld, mesh);
  }
  for (unsigned k = 0; k < node.mNumChildren; ++k) collectNode(scene, *node.mChildren[k], place, source, weld, mesh);
}

// The scene's triangles, in world units as the file's nodes place them, in double (every mesh as
// stored when the file has no nodes): rebased and welded when stored (readChecked, storedMesh).
// The whole of a file ("" when it cannot be read).
std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Whether a glTF file (.gltf text or .glb binary) declares no mesh: its JSON has no "meshes", or
// an empty array. False for any other format and for a document that does not parse.
bool gltfDeclaresNoMesh(std::string_view bytes, const std::string& lowerExtension) {
  if (lowerExtension != ".gltf" && lowerExtension != ".glb") return false;
  std::string_view text = bytes;
  if (lowerExtension == ".glb") {  // header (12 bytes), then the JSON chunk: length, type "JSON", data
    constexpr std::uint32_t kJsonChunk = 0x4E4F534A;
    std::uint32_t length = 0, type = 0;
    if (bytes.size() < 20) return false;
    std::memcpy(&length, bytes.data() + 12, 4);
    std::memcpy(&type, bytes.data() + 16, 4);
    if (type != kJsonChunk || length > bytes.size() - 20) return false;
    text = bytes.substr(20, length);
  }
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return false;
  const auto meshes = doc.find("meshes");
  return meshes == doc.end() || (meshes->is_array() && meshes->empty());
}

ParsedMesh collect(const aiScene& scene, const std::string& source) {
  ParsedMesh mesh;
  mesh.weldCorners = true;
  CornerWelder<glm::dvec3> weld(mesh.positions);
  if (scene.mRootNode) {
    collectNode(scene, *scene.mRootNode, glm::dmat4(1.0), source, weld, mesh);
  } else {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) collectMesh(*scene.mMeshes[m], m, glm::dmat4(1.0), source, weld, mesh);
  }
  return mesh;
}

// The mesh as bytes for the pipe: its float placement, counts, then the positions and triangles.
std::string serialize(const ParsedMesh& mesh) {
  const std::uint64_t counts[2] = {mesh.positions.size(), mesh.triangles.size()};
  const double placement[2] = {mesh.floatPlacement.extent, mesh.floatPlacement.reach};
  std::string out(sizeof placement + sizeof counts + counts[0] * sizeof(glm::dvec3) + counts[1] * 3 * sizeof(std::uint32_t), '\0');
  char* p = out.data();
  std::memcpy(p, placement, sizeof placement);
  p += sizeof placement;
  std::memcpy(p, counts, sizeof counts);
  p += sizeof counts;
  // An empty mesh's data() may be null, which memcpy must not be given even for 0 bytes (UBSan).
  if (counts[0] > 0) std::memcpy(p, mesh.positions.data(), counts[0] * sizeof(glm::dvec3));
  p += counts[0] * sizeof(glm::dvec3);
  if (counts[1] > 0) std::memcpy(p, mesh.triangles.data(), counts[1] * 3 * sizeof(std::uint32_t));
  return out;
}

// The child's bytes back into a mesh, checked as if they came from a file.
ParsedMesh deserialize(const std::string& bytes, const std::string& source) {
  double placement[2];
  std::uint64_t counts[2];
  const auto bad = [&] { return InputError(source, "", "", "the Assimp reader handed back a malformed mesh"); };
  if (bytes.size() < sizeof placement + sizeof counts) throw bad();
  std::memcpy(placement, bytes.data(), sizeof placement);
  std::memcpy(counts, bytes.data() + sizeof placement, sizeof counts);
  if (counts[0] > bytes.size() / sizeof(glm::dvec3) || counts[1] > bytes.size() / 12 ||
      bytes.size() != sizeof placement + sizeof counts + counts[0] * sizeof(glm::dvec3) + counts[1] * 12)
    throw bad();
  if (!(placement[0] >= 0.0 && placement[1] >= 0.0 && std::isfinite(placement[0]) && std::isfinite(placement[1])))
    throw bad();
  ParsedMesh mesh;
  mesh.weldCorners = true;
  mesh.floatPlacement = {placement[0], placement[1]};
  mesh.positions.resize(counts[0]);
  mesh.triangles.resize(counts[1]);
  const char* p = bytes.data() + sizeof placement + sizeof counts;
  if (counts[0] > 0) std::memcpy(mesh.positions.data(), p, counts[0] * sizeof(glm::dvec3));
  if (counts[1] > 0) std::memcpy(mesh.triangles.data(), p + counts[0] * sizeof(glm::dvec3), counts[1] * 12);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t k : t)
      if (k >= counts[0]) throw bad();
  for (const glm::dvec3& q : mesh.positions)
    if (!checkedPoint(q.x, q.y, q.z)) throw bad();
  return mesh;
}

}  // namespace

bool isAssimpFormat(const std::string& lowerExtension) {
  if (isOwnFormat(lowerExtension) || lowerExtension.size() < 2 || lowerExtension[0] != '.') return false;
  return Assimp::Importer().IsExtensionSupported(lowerExtension);
}

std::string assimpFormatList() {
  std::string list;  // "*.3ds;*.obj;..."
  Assimp::Importer().GetExtensionList(list);
  std::string out;
  std::size_t at = 0;
  while (at < list.size()) {
    std::size_t end = list.find(';', at);
    if (end == std::string::npos) end = list.size();
    std::string e = list.substr(at, end - at);
    if (e.rfind("*", 0) == 0) e.erase(0, 1);
    if (!e.empty() && !isOwnFormat(e)) out += (out.empty() ? "" : ", ") + e;
    at = end + 1;
  }
  return out;
}

ParsedMesh readWithAssimp(const std::string& source, const std::filesystem::path& path, std::string_view bytes,
                            const std::string& lowerExtension) {
  const IsolatedResult r = runIsolated([&] {
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, int(kRemovedComponents));
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const std::string hint = lowerExtension.substr(1);
    const aiScene* scene = path.empty()
                               ? importer.ReadFileFromMemory(bytes.data(), bytes.size(), kSteps, hint.c_str())
                               : importer.ReadFile(path.string(), kSteps);
    if (!scene) {
      const std::string why = importer.GetErrorString();
      if (why.find("No meshes remaining") != std::string::npos)  // SortByPType dropped every point and line
        throw InputError(source, "", "", "the mesh has no triangles (points and lines are dropped)");
      throw InputError(source, "", "", "Assimp cannot read it: " + why);
    }
    // Assimp flags every scene without a mesh as incomplete, also one whose geometry it could not
    // convert (an FBX with a bad index). A glTF that declares no mesh holds no triangles (as the
    // empty volume build writes): the caller accepts or refuses it (EmptyMesh). A probe's finding:
    // `check` called that file unreadable; a second reader's, that a broken FBX then passed.
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE && scene->mNumMeshes == 0 &&
        gltfDeclaresNoMesh(path.empty() ? bytes : std::string_view(readAll(path)), lowerExtension))
      return serialize(ParsedMesh{});
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
      throw InputError(source, "", "", "Assimp read it only in part (AI_SCENE_FLAGS_INCOMPLETE)");
    if (scene->mRootNode) checkNodes(*scene->mRootNode, glm::dmat4(1.0), "", source);
    return serialize(collect(*scene, source));
  });
  if (!r.ok) {
    // The child's InputError arrives as its message, which names the source already.
    if (r.output.rfind(source, 0) == 0) throw InputError(source, "", "", r.output.substr(source.size() + 2));
    throw InputError(source, "", "", "the Assimp reader " + r.output);
  }
  return deserialize(r.output, source);
}

}  // namespace shadowvol::mesh_readers
