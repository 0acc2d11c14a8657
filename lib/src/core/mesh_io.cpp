#include "shadowvol/mesh_io.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <glm/geometric.hpp>
#include <system_error>
#include <unistd.h>

#include "mesh_readers/obj_reader.h"
#include "mesh_readers/off_reader.h"
#include "mesh_readers/ply_reader.h"
#include "mesh_readers/stl_reader.h"
#include "shadowvol/error.h"
#include "shadowvol/temporary_files.h"

namespace shadowvol {
namespace {

// The whole file: the readers walk it in memory, every loop bounded by its size.
std::string fileBytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path.string(), "", "", "mesh file not found");
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string(), "", "", "not a regular file (a folder, device or pipe)");
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

std::string lowerText(std::string_view text) {
  std::string e(text);
  for (auto& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

std::string lowerExtension(const std::filesystem::path& p) { return lowerText(p.extension().string()); }

void checkReadableExtension(const std::string& ext, const std::string& source) {
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw InputError(source, "", ext, "unsupported mesh format (use .obj, .off, .ply or .stl)");
}

}  // namespace

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write) {
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
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError(path.string(), "", "", "cannot write the file: " + ec.message());
  }
}

TriangleMesh parseTriangleMesh(std::string_view bytes, std::string_view format, const std::string& source) {
  const std::string ext = lowerText(format);
  checkReadableExtension(ext, source);
  // Our own strict readers (mesh_readers/), not OpenMesh's: see the comment atop each reader for
  // what OpenMesh 9 did with the same hostile file (crashes, endless loops, unbounded allocation,
  // silently dropped or shifted faces).
  TriangleMesh mesh = ext == ".obj"   ? mesh_readers::readObj(source, bytes)
                      : ext == ".off" ? mesh_readers::readOff(source, bytes)
                      : ext == ".ply" ? mesh_readers::readPly(source, bytes)
                                      : mesh_readers::readStl(source, bytes);
  if (mesh.triangles.empty()) throw InputError(source, "", "", "the mesh has no triangles");
  return mesh;
}

TriangleMesh readTriangleMesh(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  checkReadableExtension(ext, path.string());  // before touching the file
  return parseTriangleMesh(fileBytes(path), ext, path.string());
}

namespace {

void checkMeshExtension(const std::filesystem::path& path, const MeshFrame& frame) {
  const std::string ext = lowerExtension(path);
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw InputError(path.string(), "", ext, "unsupported mesh format (use .ply, .obj, .off or .stl)");
  if (ext == ".stl" && frame.worldCoordinates)
    throw InputError(path.string(), "", ext,
                     "STL stores single-precision coordinates only: write world coordinates as .ply, .obj or .off");
}

std::string originText(const glm::dvec3& o) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "shadowvol origin %.17g %.17g %.17g", o.x, o.y, o.z);
  return buf;
}

// The writer for both mesh kinds: `positions` holds float or double 3-vectors, stored coordinates.
template <class Positions, class Triangles>
void writeMesh(const Positions& P, const Triangles& T, const std::filesystem::path& path, const MeshFrame& frame) {
  // Written directly rather than through OpenMesh: its half-edge kernel refuses non-manifold faces,
  // which would silently drop triangles of a scene soup. Tests read these files back with OpenMesh.
  checkMeshExtension(path, frame);
  const std::string ext = lowerExtension(path);
  const bool world = frame.worldCoordinates;
  const bool namedOrigin = !world && frame.origin != glm::dvec3(0.0);
  auto at = [&](std::size_t k) { return world ? glm::dvec3(P[k]) + frame.origin : glm::dvec3(P[k]); };
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(path.string(), "", "", "cannot create the file");
    char buf[160];
    if (ext == ".ply") {
      const char* type = world ? "double" : "float";
      out << "ply\nformat binary_little_endian 1.0\ncomment written by shadowvol\n";
      if (namedOrigin) out << "comment " << originText(frame.origin) << " (world = vertex + origin)\n";
      out << "element vertex " << P.size() << "\nproperty " << type << " x\nproperty " << type << " y\nproperty "
          << type << " z\nelement face " << T.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
      static_assert(std::endian::native == std::endian::little, "PLY writer assumes a little-endian host");
      for (std::size_t k = 0; k < P.size(); ++k) {
        if (world) {
          const glm::dvec3 p = at(k);
          out.write(reinterpret_cast<const char*>(&p), sizeof p);
        } else {
          const glm::vec3 p(P[k]);
          out.write(reinterpret_cast<const char*>(&p), sizeof p);
        }
      }
      for (const auto& t : T) {
        const unsigned char n = 3;
        out.write(reinterpret_cast<const char*>(&n), 1);
        out.write(reinterpret_cast<const char*>(t.data()), 12);
      }
    } else if (ext == ".obj" || ext == ".off") {
      // Stored floats print exactly with 9 digits; world doubles need 17.
      const char* format = world ? "%.17g %.17g %.17g\n" : "%.9g %.9g %.9g\n";
      if (ext == ".obj") {
        out << "# written by shadowvol\n";
        if (namedOrigin) out << "# " << originText(frame.origin) << " (world = vertex + origin)\n";
      } else {
        out << "OFF\n" << P.size() << ' ' << T.size() << " 0\n";
      }
      for (std::size_t k = 0; k < P.size(); ++k) {
        const glm::dvec3 p = world ? at(k) : glm::dvec3(glm::vec3(P[k]));
        std::snprintf(buf, sizeof buf, format, p.x, p.y, p.z);
        if (ext == ".obj") out << "v ";
        out << buf;
      }
      for (const auto& t : T) {
        if (ext == ".obj") out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
        else out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
      }
    } else {  // binary STL: 80-byte header, count, then normal + 3 vertices + attribute per triangle
      char header[80] = {};
      const std::string text = namedOrigin ? originText(frame.origin) : "binary STL written by shadowvol";
      std::snprintf(header, sizeof header, "%s", text.c_str());
      out.write(header, 80);
      const auto n = static_cast<std::uint32_t>(T.size());
      out.write(reinterpret_cast<const char*>(&n), 4);
      for (const auto& t : T) {
        const glm::vec3 a(P[t[0]]), b(P[t[1]]), c(P[t[2]]);
        glm::vec3 nrm = glm::cross(b - a, c - a);
        const float len = glm::length(nrm);
        nrm = len > 0.0f ? nrm / len : glm::vec3(0.0f);
        const glm::vec3 v[4] = {nrm, a, b, c};
        out.write(reinterpret_cast<const char*>(v), 48);
        const std::uint16_t attr = 0;
        out.write(reinterpret_cast<const char*>(&attr), 2);
      }
    }
    out.flush();
    if (!out) throw InputError(path.string(), "", "", "writing the file failed (disk full?)");
  });
}

}  // namespace

void writeTriangleMesh(const TriangleMesh& mesh, const std::filesystem::path& path, const MeshFrame& frame) {
  writeMesh(mesh.positions, mesh.triangles, path, frame);
}

void writeVolumeMesh(const VolumeMesh& mesh, const std::filesystem::path& path, bool worldCoordinates) {
  writeMesh(mesh.positions, mesh.triangles, path, MeshFrame{mesh.origin, worldCoordinates});
}

}  // namespace shadowvol
