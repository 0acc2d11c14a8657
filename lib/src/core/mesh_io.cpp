#include "shadowvol/mesh_io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numeric>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <system_error>
#include <unistd.h>

#include "mesh_readers/assimp_reader.h"
#include "mesh_readers/obj_reader.h"
#include "mesh_readers/off_reader.h"
#include "mesh_readers/own_formats.h"
#include "mesh_readers/parsed_mesh.h"
#include "mesh_readers/polygon_triangulation.h"
#include "mesh_readers/ply_reader.h"
#include "mesh_readers/stl_reader.h"
#include "mesh_readers/text_lines.h"
#include "mesh_writers/gltf_writer.h"
#include "shadowvol/error.h"
#include "shadowvol/temporary_files.h"

namespace shadowvol {
namespace {

void checkRegularFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(path.string(), "", "", ec ? "mesh file cannot be reached: " + ec.message() : "mesh file not found");
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string(), "", "", "not a regular file (a folder, device or pipe)");
}

// The whole file: the readers walk it in memory, every loop bounded by its size.
std::string fileBytes(const std::filesystem::path& path) {
  checkRegularFile(path);
  std::ifstream in(path, std::ios::binary);
  std::string bytes;
  if (in) {
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    if (size >= 0) {
      bytes.resize(std::size_t(size));
      in.read(bytes.data(), size);
    }
  }
  if (!in) throw InputError(path.string(), "", "", "cannot read the file");
  return bytes;
}

std::string lowerExtension(const std::filesystem::path& p) { return mesh_readers::lowerCase(p.extension().string()); }

void checkReadableExtension(const std::string& ext, const std::string& source) {
  if (!mesh_readers::isOwnFormat(ext) && !mesh_readers::isAssimpFormat(ext))
    throw InputError(source, "", ext,
                     "unsupported mesh format (use .obj, .off, .ply, .stl or a format Assimp reads: " +
                         mesh_readers::assimpFormatList() + ")");
}

// Our own strict readers (mesh_readers/), not OpenMesh's: see the comment atop each reader for
// what OpenMesh 9 did with the same hostile file (crashes, endless loops, unbounded allocation,
// silently dropped or shifted faces). The other formats go to Assimp, in a child process.
// `rebase`: store the mesh from its storageOrigin, else from 0.
RebasedMesh readChecked(std::string_view bytes, const std::string& ext, const std::string& source,
                        const std::filesystem::path& path, EmptyMesh empty, bool rebase) {
  mesh_readers::ParsedMesh parsed = ext == ".obj"   ? mesh_readers::readObj(source, bytes)
                                    : ext == ".off" ? mesh_readers::readOff(source, bytes)
                                    : ext == ".ply" ? mesh_readers::readPly(source, bytes)
                                    : ext == ".stl" ? mesh_readers::readStl(source, bytes)
                                                    : mesh_readers::readWithAssimp(source, path, bytes, ext);
  for (const auto& t : parsed.triangles)  // every reader checks its indices; this keeps a slip from memory
    for (const std::uint32_t i : t)
      if (i >= parsed.positions.size())
        throw InputError(source, "", std::to_string(i + 1),
                         "a face names a vertex the file does not have (it has " +
                             std::to_string(parsed.positions.size()) + ")");
  mesh_readers::triangulateNonConvexPolygons(parsed);
  RebasedMesh read;
  if (rebase) read.origin = mesh_readers::storageOrigin(parsed);
  read.mesh = mesh_readers::storedMesh(parsed, read.origin);
  read.floatExtent = parsed.floatPlacement.extent;
  read.floatReach = parsed.floatPlacement.reach;
  if (read.mesh.triangles.empty() && empty == EmptyMesh::Refuse)
    throw InputError(source, "", "", "the mesh has no triangles");
  return read;
}

RebasedMesh readFile(const std::filesystem::path& path, EmptyMesh empty, bool rebase) {
  const std::string ext = lowerExtension(path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))  // named as such, whatever its extension (a probe's finding)
    throw InputError(path.string(), "", "", "a folder, not a mesh file");
  checkReadableExtension(ext, path.string());  // before touching the file
  if (mesh_readers::isOwnFormat(ext)) return readChecked(fileBytes(path), ext, path.string(), path, empty, rebase);
  checkRegularFile(path);
  return readChecked({}, ext, path.string(), path, empty, rebase);  // Assimp opens it (and its .bin, textures)
}

// Where writeAtomically writes `path`: the path itself, or the file a symbolic link names (written
// through, as open() would). Refuses a folder, a device, pipe or socket (renaming onto it would
// replace it: a probe's `--out` onto a FIFO or a device node, as root onto any device), a link to
// nothing, and a file its owner made read-only (the rename would not ask, as cp does).
std::filesystem::path writeTarget(const std::filesystem::path& path) {
  std::error_code ec;
  const auto link = std::filesystem::symlink_status(path, ec);
  std::filesystem::path target = path;
  if (link.type() == std::filesystem::file_type::symlink) {
    target = std::filesystem::canonical(path, ec);
    if (ec) throw InputError(path.string(), "", "", "is a symbolic link to a file that does not exist: " + ec.message());
  }
  const auto st = std::filesystem::status(target, ec);
  if (st.type() == std::filesystem::file_type::directory)  // (renaming onto it failed with "Success")
    throw InputError(path.string(), "", "", "is a folder: a file cannot be written in its place");
  if (st.type() != std::filesystem::file_type::not_found && st.type() != std::filesystem::file_type::regular)
    throw InputError(path.string(), "", "", "is not a regular file (a device, pipe or socket): it would be replaced");
  // The permission bits as well as access(): root may write anything, yet a file nobody may write
  // was made read-only on purpose (a twenty-second probe's 0444 file was replaced under root).
  const bool noWriteBits =
      (st.permissions() & (std::filesystem::perms::owner_write | std::filesystem::perms::group_write |
                           std::filesystem::perms::others_write)) == std::filesystem::perms::none;
  if (st.type() == std::filesystem::file_type::regular && (noWriteBits || ::access(target.c_str(), W_OK) != 0))
    throw InputError(path.string(), "", "", "is read-only: it is not replaced");
  return target;
}

}  // namespace

void writeAtomically(const std::filesystem::path& requested,
                     const std::function<void(const std::filesystem::path&)>& write) {
  const std::filesystem::path path = writeTarget(requested);
  // Keep the real extension last: OpenMesh picks the writer by it.
  std::filesystem::path tmp = path;
  std::string name = ".";  // built with += (GCC 12 warns falsely on "." + std::string)
  name += path.stem().string();
  name += ".tmp";
  name += std::to_string(::getpid());
  name += path.extension().string();
  tmp.replace_filename(name);
  const TemporaryFileGuard guard(tmp);  // removed if a signal ends the process meanwhile
  try {
    write(tmp);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
  std::error_code ec;
  if (const auto st = std::filesystem::status(path, ec); st.type() == std::filesystem::file_type::regular)
    std::filesystem::permissions(tmp, st.permissions(), ec);  // a replaced file keeps its mode
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError(path.string(), "", "", "cannot write the file: " + ec.message());
  }
  noteOutputPlaced(path);  // part of a several-file result: removed if a signal ends the command
}

void createFolders(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(dir.string(), "", "", "cannot create the folder" + (ec ? ": " + ec.message() : std::string()));
}

TriangleMesh parseTriangleMesh(std::string_view bytes, std::string_view format, const std::string& source) {
  const std::string ext = mesh_readers::lowerCase(format);
  checkReadableExtension(ext, source);
  return readChecked(bytes, ext, source, {}, EmptyMesh::Refuse, false).mesh;
}

TriangleMesh readTriangleMesh(const std::filesystem::path& path, EmptyMesh empty) {
  return readFile(path, empty, false).mesh;
}

RebasedMesh readRebasedTriangleMesh(const std::filesystem::path& path, EmptyMesh empty) {
  return readFile(path, empty, true);
}

namespace {

// glTF's buffer and GLB's total length are 32-bit: 12 bytes per vertex and per triangle must fit.
constexpr std::size_t kMaxGltfElements = 170'000'000;

bool isGltf(const std::string& ext) { return ext == ".gltf" || ext == ".glb"; }

void checkMeshExtension(const std::filesystem::path& path, const MeshFrame& frame) {
  const std::string ext = lowerExtension(path);
  if (!isMeshOutputFormat(path))
    throw InputError(path.string(), "", ext, std::string("unsupported mesh format (use ") + kMeshOutputFormats + ")");
  if (ext == ".stl" && frame.worldCoordinates)
    throw InputError(path.string(), "", ext,
                     "STL stores single-precision coordinates only: write world coordinates as .ply, .obj or .off");
}

// The origin's doubles with 17 significant digits, or `shortest`: the shortest text that reads back
// as each (numberText: "1e+06" for 1000000), for STL's 80-byte header.
std::string originText(const glm::dvec3& o, bool shortest = false) {
  if (shortest) return "shadowvol origin " + numberText(o.x) + " " + numberText(o.y) + " " + numberText(o.z);
  char buf[128];
  std::snprintf(buf, sizeof buf, "shadowvol origin %.17g %.17g %.17g", o.x, o.y, o.z);
  return buf;
}

// STL's header text: the origin, in full, in at most 79 bytes (the 80th ends the string).
std::string stlOriginText(const glm::dvec3& o) {
  const std::string full = originText(o);
  return full.size() < 80 ? full : originText(o, true);
}

// What every format writer gets: the stored coordinates, how to write them, and the stream.
template <class Positions, class Triangles>
struct MeshOut {
  const Positions& P;
  const Triangles& T;
  const MeshFrame& frame;
  std::ostream& out;
  bool world() const { return frame.worldCoordinates; }
  bool namedOrigin() const { return !world() && frame.origin != glm::dvec3(0.0); }
  glm::dvec3 at(std::size_t k) const { return world() ? glm::dvec3(P[k]) + frame.origin : glm::dvec3(P[k]); }
};

template <class M>
void writePly(const M& m) {
  const char* type = m.world() ? "double" : "float";
  m.out << "ply\nformat binary_little_endian 1.0\ncomment written by shadowvol\n";
  if (m.namedOrigin()) m.out << "comment " << originText(m.frame.origin) << " (world = vertex + origin)\n";
  m.out << "element vertex " << m.P.size() << "\nproperty " << type << " x\nproperty " << type << " y\nproperty "
        << type << " z\nelement face " << m.T.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
  static_assert(std::endian::native == std::endian::little, "PLY writer assumes a little-endian host");
  for (std::size_t k = 0; k < m.P.size(); ++k) {
    if (m.world()) {
      const glm::dvec3 p = m.at(k);
      m.out.write(reinterpret_cast<const char*>(&p), sizeof p);
    } else {
      const glm::vec3 p(m.P[k]);
      m.out.write(reinterpret_cast<const char*>(&p), sizeof p);
    }
  }
  for (const auto& t : m.T) {
    const unsigned char n = 3;
    m.out.write(reinterpret_cast<const char*>(&n), 1);
    m.out.write(reinterpret_cast<const char*>(t.data()), 12);
  }
}

template <class M>
void writeObjOrOff(const M& m, bool obj) {
  // Stored floats print exactly with 9 digits; world doubles need 17.
  const char* format = m.world() ? "%.17g %.17g %.17g\n" : "%.9g %.9g %.9g\n";
  if (obj) {
    m.out << "# written by shadowvol\n";
    if (m.namedOrigin()) m.out << "# " << originText(m.frame.origin) << " (world = vertex + origin)\n";
  } else {
    m.out << "OFF\n" << m.P.size() << ' ' << m.T.size() << " 0\n";
  }
  char buf[160];
  for (std::size_t k = 0; k < m.P.size(); ++k) {
    const glm::dvec3 p = m.world() ? m.at(k) : glm::dvec3(glm::vec3(m.P[k]));
    std::snprintf(buf, sizeof buf, format, p.x, p.y, p.z);
    if (obj) m.out << "v ";
    m.out << buf;
  }
  for (const auto& t : m.T) {
    if (obj) m.out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    else m.out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
}

template <class M>
void writeStl(const M& m) {  // binary: 80-byte header, count, then normal + 3 vertices + attribute per triangle
  char header[80] = {};
  const std::string text = m.namedOrigin() ? stlOriginText(m.frame.origin) : "binary STL written by shadowvol";
  std::snprintf(header, sizeof header, "%s", text.c_str());
  m.out.write(header, 80);
  const auto n = static_cast<std::uint32_t>(m.T.size());
  m.out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : m.T) {
    const glm::vec3 a(m.P[t[0]]), b(m.P[t[1]]), c(m.P[t[2]]);
    glm::vec3 nrm = glm::cross(b - a, c - a);
    const float len = glm::length(nrm);
    nrm = len > 0.0f ? nrm / len : glm::vec3(0.0f);
    const glm::vec3 v[4] = {nrm, a, b, c};
    m.out.write(reinterpret_cast<const char*>(v), 48);
    const std::uint16_t attr = 0;
    m.out.write(reinterpret_cast<const char*>(&attr), 2);
  }
}

// glTF stores floats: the stored coordinates, with the origin as the node's translation (also for
// world coordinates: stored + origin is then carried exactly by the pair).
template <class M>
void writeGltfFile(const M& m, const std::filesystem::path& path, bool binary) {
  if (m.P.size() > kMaxGltfElements || m.T.size() > kMaxGltfElements)
    throw InputError(path.string(), "", std::to_string(m.T.size()) + " triangles",
                     "too large for one glTF buffer (at most " + std::to_string(kMaxGltfElements) +
                         " vertices and triangles): write .ply");
  mesh_writers::GltfMesh g;
  g.positions.reserve(m.P.size());
  for (const auto& p : m.P) g.positions.emplace_back(glm::vec3(p));
  g.triangles.assign(m.T.begin(), m.T.end());
  g.origin = m.frame.origin;
  g.name = path.stem().string();
  mesh_writers::writeGltf(m.out, g, binary);
}

// The writer for both mesh kinds: `positions` holds float or double 3-vectors, stored coordinates.
template <class Positions, class Triangles>
void writeMesh(const Positions& P, const Triangles& T, const std::filesystem::path& path, const MeshFrame& frame) {
  // Written directly rather than through OpenMesh: its half-edge kernel refuses non-manifold faces,
  // which would silently drop triangles of a scene soup. Tests read these files back with OpenMesh
  // (and the glTF files with tinygltf).
  checkMeshExtension(path, frame);
  // Every coordinate as it will be written must be finite (a probe's finding: 1e300 in single
  // precision was written as inf, a file that check and the readers refuse).
  const double limit = frame.worldCoordinates ? std::numeric_limits<double>::max() : std::numeric_limits<float>::max();
  for (std::size_t k = 0; k < P.size(); ++k) {
    const glm::dvec3 p = frame.worldCoordinates ? glm::dvec3(P[k]) + frame.origin : glm::dvec3(P[k]);
    if (!(std::abs(p.x) <= limit && std::abs(p.y) <= limit && std::abs(p.z) <= limit))  // NaN too
      throw InputError(path.string(), "vertex " + std::to_string(k), numberText(glm::dvec3(P[k]).x) + " " +
                           numberText(glm::dvec3(P[k]).y) + " " + numberText(glm::dvec3(P[k]).z),
                       frame.worldCoordinates ? "is not finite"
                                              : "does not fit single precision: write it in double (world "
                                                "coordinates, .ply, .obj or .off) or move the mesh nearer its origin");
  }
  const std::string ext = lowerExtension(path);
  // STL's header holds 80 bytes: an origin that does not fit in full is refused, not cut (a
  // twenty-second probe's header lost the last number's exponent).
  if (ext == ".stl" && !frame.worldCoordinates && frame.origin != glm::dvec3(0.0) &&
      stlOriginText(frame.origin).size() >= 80)
    throw InputError(path.string(), "origin", stlOriginText(frame.origin).substr(17),
                     "does not fit STL's 80-byte header in full: write .ply, .obj or .gltf, which name it");
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(path.string(), "", "", "cannot create the file");
    const MeshOut<Positions, Triangles> m{P, T, frame, out};
    if (ext == ".ply") writePly(m);
    else if (ext == ".obj" || ext == ".off") writeObjOrOff(m, ext == ".obj");
    else if (ext == ".stl") writeStl(m);
    else writeGltfFile(m, path, ext == ".glb");
    out.flush();
    if (!out) throw InputError(path.string(), "", "", "writing the file failed (disk full?)");
  });
}

}  // namespace

glm::dvec3 floatStorageOrigin(std::span<const glm::dvec3> positions,
                              std::span<const std::array<std::uint32_t, 3>> triangles) {
  // Over the vertices the faces use: a stray one near 0 (which a scene leaves out) must not keep
  // a mesh far out from being rebased.
  std::vector<bool> used(positions.size(), false);
  for (const auto& t : triangles)
    for (const std::uint32_t i : t) used[i] = true;
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (used[i]) {
      lo = glm::min(lo, positions[i]);
      hi = glm::max(hi, positions[i]);
    }
  if (lo.x > hi.x) return glm::dvec3(0.0);  // no face
  const glm::dvec3 reach = glm::max(glm::abs(lo), glm::abs(hi));
  const double step = std::max({reach.x, reach.y, reach.z}) * std::ldexp(1.0, -23);  // float's spacing there, at most
  const double extent = glm::length(hi - lo);
  if (step == 0.0 || extent == 0.0 || extent >= mesh_readers::kMinStoredSteps * step) return glm::dvec3(0.0);
  return 0.5 * lo + 0.5 * hi;  // (lo + hi) / 2 without overflow near the float range
}

bool isMeshOutputFormat(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl" || isGltf(ext);
}

void writeTriangleMesh(const TriangleMesh& mesh, const std::filesystem::path& path, const MeshFrame& frame) {
  writeMesh(mesh.positions, mesh.triangles, path, frame);
}

namespace {

// Vertices equal to an earlier one, and triangles with two equal corners, over positions P.
template <class Positions, class Triangles>
void countCoincident(const Positions& P, const Triangles& T, WrittenVolume& w) {
  std::vector<std::uint32_t> order(P.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
    const auto &p = P[x], &q = P[y];
    return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : p.z < q.z;
  });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (P[order[k]] == P[order[k - 1]]) ++w.coincidentVertices;
  for (const auto& t : T)
    if (P[t[0]] == P[t[1]] || P[t[1]] == P[t[2]] || P[t[2]] == P[t[0]]) ++w.collapsedTriangles;
}

}  // namespace

// The shift rounded to a multiple of a power of two about a quarter of the volume's extent, each
// component, so that its text is short and exact (an STL header holds 80 bytes; a centre a hair
// off zero printed as 1.2420184702932602e-07) while the positions stay within about the extent of
// it; 0 stays 0.
namespace {
glm::dvec3 roundedShift(const glm::dvec3& shift, const VolumeMesh& mesh) {
  if (shift == glm::dvec3(0.0)) return shift;
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const auto& t : mesh.triangles)
    for (const std::uint32_t i : t) lo = glm::min(lo, mesh.positions[i]), hi = glm::max(hi, mesh.positions[i]);
  const double extent = glm::length(hi - lo);
  if (!(extent > 0.0)) return shift;
  const double q = std::ldexp(1.0, int(std::floor(std::log2(extent / 4.0))));
  return glm::round(shift / q) * q;
}
}  // namespace

std::size_t coincidentVertices(const VolumeMesh& mesh) {
  WrittenVolume w;
  countCoincident(mesh.positions, std::vector<std::array<std::uint32_t, 3>>{}, w);
  return w.coincidentVertices;
}

WrittenVolume writeVolumeMesh(const VolumeMesh& mesh, const std::filesystem::path& path, bool worldCoordinates) {
  WrittenVolume w;
  w.origin = mesh.origin;
  if (worldCoordinates && !isGltf(lowerExtension(path))) {  // doubles, world = position + origin
    writeMesh(mesh.positions, mesh.triangles, path, MeshFrame{mesh.origin, true});
    countCoincident(mesh.positions, mesh.triangles, w);
    return w;
  }
  const glm::dvec3 shift = roundedShift(floatStorageOrigin(mesh.positions, mesh.triangles), mesh);
  w.origin = mesh.origin + shift;
  std::vector<glm::vec3> written(mesh.positions.size());  // as the file stores them
  for (std::size_t k = 0; k < written.size(); ++k) written[k] = glm::vec3(mesh.positions[k] - shift);
  if (shift == glm::dvec3(0.0))
    writeMesh(mesh.positions, mesh.triangles, path, MeshFrame{mesh.origin, worldCoordinates});
  else {
    std::vector<glm::dvec3> moved(mesh.positions.size());
    for (std::size_t k = 0; k < moved.size(); ++k) moved[k] = mesh.positions[k] - shift;
    writeMesh(moved, mesh.triangles, path, MeshFrame{w.origin, worldCoordinates});
  }
  countCoincident(written, mesh.triangles, w);
  return w;
}

}  // namespace shadowvol
