#include "shadowvol/mesh_io.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <glm/geometric.hpp>
#include <system_error>
#include <unistd.h>

// OpenMesh's IO header must come before the mesh kernel headers.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "shadowvol/error.h"

namespace shadowvol {
namespace {

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

std::string lowerExtension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  for (auto& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
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

TriangleMesh readTriangleMesh(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw InputError(path.string(), "", ext, "unsupported mesh format (use .obj, .off, .ply or .stl)");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path.string(), "", "", "mesh file not found");
  OMesh m;
  OpenMesh::IO::Options opt;
  if (!OpenMesh::IO::read_mesh(m, path.string(), opt))
    throw InputError(path.string(), "", "", "cannot read the mesh (unreadable or malformed)");
  TriangleMesh out;
  out.positions.reserve(m.n_vertices());
  for (const auto vh : m.vertices()) {
    const auto& p = m.point(vh);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw InputError(path.string(), "vertex " + std::to_string(vh.idx()),
                       std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]),
                       "non-finite vertex coordinate");
    out.positions.emplace_back(p[0], p[1], p[2]);
  }
  out.triangles.reserve(m.n_faces());
  for (const auto fh : m.faces()) {
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    for (const auto vh : m.fv_range(fh)) {
      if (k < 3) t[k] = std::uint32_t(vh.idx());
      ++k;
    }
    if (k == 3) out.triangles.push_back(t);
  }
  if (out.triangles.empty()) throw InputError(path.string(), "", "", "the mesh has no triangles");
  return out;
}

void writeTriangleMesh(const TriangleMesh& mesh, const std::filesystem::path& path) {
  // Written directly rather than through OpenMesh: its half-edge kernel refuses non-manifold faces,
  // which would silently drop triangles of a scene soup. Tests read these files back with OpenMesh.
  const std::string ext = lowerExtension(path);
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw InputError(path.string(), "", ext, "unsupported mesh format (use .ply, .obj, .off or .stl)");
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(path.string(), "", "", "cannot create the file");
    const auto& P = mesh.positions;
    const auto& T = mesh.triangles;
    char buf[128];
    if (ext == ".ply") {
      out << "ply\nformat binary_little_endian 1.0\ncomment written by shadowvol\n"
          << "element vertex " << P.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
          << "element face " << T.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
      static_assert(std::endian::native == std::endian::little, "PLY writer assumes a little-endian host");
      out.write(reinterpret_cast<const char*>(P.data()), std::streamsize(P.size() * sizeof(glm::vec3)));
      for (const auto& t : T) {
        const unsigned char n = 3;
        out.write(reinterpret_cast<const char*>(&n), 1);
        out.write(reinterpret_cast<const char*>(t.data()), 12);
      }
    } else if (ext == ".obj") {
      out << "# written by shadowvol\n";
      for (const auto& p : P) {
        std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
        out << buf;
      }
      for (const auto& t : T) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    } else if (ext == ".off") {
      out << "OFF\n" << P.size() << ' ' << T.size() << " 0\n";
      for (const auto& p : P) {
        std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", p.x, p.y, p.z);
        out << buf;
      }
      for (const auto& t : T) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    } else {  // binary STL: 80-byte header, count, then normal + 3 vertices + attribute per triangle
      char header[80] = "binary STL written by shadowvol";
      out.write(header, 80);
      const auto n = static_cast<std::uint32_t>(T.size());
      out.write(reinterpret_cast<const char*>(&n), 4);
      for (const auto& t : T) {
        const glm::vec3 a = P[t[0]], b = P[t[1]], c = P[t[2]];
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

}  // namespace shadowvol
