// Helpers shared by the test folders.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/light.h"
#include "shadowvol/scene.h"
#include "shadowvol/triangle_mesh.h"

namespace shadowvol::test {

/// A fresh empty folder under the system temp dir, named after the running test.
inline std::filesystem::path tempDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  auto dir = std::filesystem::temp_directory_path() / "shadowvol-tests" /
             (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void writeText(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

/// The whole of a file as text ("" when it cannot be read).
inline std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// A triangle mesh's signed volume (positive when it is closed and faces outward), in double.
inline double signedVolume(const TriangleMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles)
    v += glm::dot(glm::dvec3(m.positions[t[0]]),
                  glm::cross(glm::dvec3(m.positions[t[1]]), glm::dvec3(m.positions[t[2]]))) /
         6.0;
  return v;
}

/// Another process holding an exclusive flock on `folder` (as another shadowvol run's OutputLock
/// does) from construction, once it has it, until release() or destruction. One at a time: a
/// second one's process would hold the first one's pipe open.
class FolderHeldElsewhere {
 public:
  explicit FolderHeldElsewhere(const std::filesystem::path& folder) {
    int held[2], release[2];
    if (::pipe2(held, O_CLOEXEC) != 0) return;
    if (::pipe2(release, O_CLOEXEC) != 0) {
      ::close(held[0]);
      ::close(held[1]);
      return;
    }
    child_ = ::fork();
    if (child_ == 0) {
      ::close(held[0]);
      ::close(release[1]);  // or the parent's close would never end the read below
      const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
      const char ok = (fd >= 0 && ::flock(fd, LOCK_EX) == 0) ? 'y' : 'n';
      [[maybe_unused]] const auto w = ::write(held[1], &ok, 1);
      char c;
      [[maybe_unused]] const auto r = ::read(release[0], &c, 1);  // until the parent writes or closes
      std::_Exit(0);
    }
    ::close(held[1]);
    ::close(release[0]);
    releaseFd_ = release[1];
    char ok = 'n';
    holding_ = child_ > 0 && ::read(held[0], &ok, 1) == 1 && ok == 'y';
    ::close(held[0]);
  }
  ~FolderHeldElsewhere() { release(); }
  /// Lets go of the lock: the other process ends.
  void release() {
    if (releaseFd_ >= 0) ::close(releaseFd_);
    if (child_ > 0) ::waitpid(child_, nullptr, 0);
    releaseFd_ = child_ = -1;
    holding_ = false;
  }
  FolderHeldElsewhere(const FolderHeldElsewhere&) = delete;
  FolderHeldElsewhere& operator=(const FolderHeldElsewhere&) = delete;
  bool holding() const { return holding_; }

 private:
  pid_t child_ = -1;
  int releaseFd_ = -1;
  bool holding_ = false;
};

inline std::filesystem::path sourceDir() { return SV_SOURCE_DIR; }

/// The default scene's layout as scene JSON (ground, sphere of detail 3, spot light, camera),
/// scaled by `scale` about the world origin and then moved by `offset`.
inline std::string movedDefaultScene(const glm::dvec3& offset, double scale = 1.0, int width = 640, int height = 480) {
  auto at = [&](double x, double y, double z) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "[%.17g, %.17g, %.17g]", x * scale + offset.x, y * scale + offset.y,
                  z * scale + offset.z);
    return std::string(buf);
  };
  auto num = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  return R"({"objects":[{"type":"plane","size":)" + num(20 * scale) + R"(,"transform":{"translate":)" + at(0, 0, 0) +
         R"(}},{"type":"sphere","radius":)" + num(scale) + R"(,"detail":3,"transform":{"translate":)" + at(0, 2, 0) +
         R"(}}],"light":{"type":"spot","position":)" + at(3, 9, 2) + R"(,"target":)" + at(-0.3, 0, -0.2) +
         R"(,"fov":55},"camera":{"eye":)" + at(0, 6, 11) + R"(,"target":)" + at(0, 1, 0) + R"(,"width":)" +
         std::to_string(width) + R"(,"height":)" + std::to_string(height) + "}}";
}

/// `mesh` with every triangle's corners stored apart, as STL files store them (no shared vertex).
inline TriangleMesh splitVertices(const TriangleMesh& mesh) {
  TriangleMesh split;
  for (const auto& t : mesh.triangles) {
    const auto base = std::uint32_t(split.positions.size());
    for (auto k : t) split.positions.push_back(mesh.positions[k]);
    split.triangles.push_back({base, base + 1, base + 2});
  }
  return split;
}

/// A directional light straight down from y = 5 over a 8 x 8 square (half extent 4), near 0.5.
inline Light directionalDown(double farPlane = 12.0) {
  Light light;
  light.type = LightType::Directional;
  light.position = {0, 5, 0};
  light.direction = {0, -1, 0};
  light.halfExtent = 4.0;
  light.nearPlane = 0.5;
  light.farPlane = farPlane;
  return light;
}

// A scene file's text parsed as `name` (relative paths from "."), its light and camera fitted as
// loading a file does.
inline Scene fittedScene(const std::string& json, const std::string& name) {
  Scene scene = parseScene(json, name, ".").scene;
  fitLightAndCamera(scene);
  return scene;
}

/// A scene of these objects under a directional light straight down (far plane 6), no camera set.
inline Scene sceneWith(std::vector<SceneObject> objects) {
  Scene s;
  s.objects = std::move(objects);
  s.light = directionalDown(6.0);
  return s;
}

/// A square plate of side `size` at height y, single-sided and facing up (+y), with a square hole
/// [x0, x1] x [z0, z1] inside it: a 3 x 3 grid of cells on the lines x = -size/2, x0, x1, size/2
/// (z likewise) without its middle cell. Welded; its rims are the 4 outer edges and the hole's 4.
inline TriangleMesh holedPlate(double size, double y, double x0, double x1, double z0, double z1) {
  const double xs[4] = {-0.5 * size, x0, x1, 0.5 * size}, zs[4] = {-0.5 * size, z0, z1, 0.5 * size};
  TriangleMesh m;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) m.positions.push_back(glm::vec3(float(xs[i]), float(y), float(zs[j])));
  const auto at = [](int i, int j) { return std::uint32_t(4 * j + i); };
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      if (i == 1 && j == 1) continue;  // the hole
      m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});  // counter-clockwise from above
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  return m;
}

/// A closed wedge under a directional light straight down whose sloped face is lit at the cosine
/// `cosToLight`: the right triangle (0, 0), (width, 0), (0, height) in x-y, extruded over z in
/// [-1, 1], width = height cos / sin. Its bottom is the back face behind the slope. The light's
/// window (half extent width, centred over x = width / 2) puts half of the map's columns on the
/// slope; a camera looks at the wedge's side.
inline Scene grazedWedgeScene(double cosToLight, double height = 20.0) {
  const double width = height * cosToLight / std::sqrt(1.0 - cosToLight * cosToLight);
  const float w = float(width), h = float(height);
  TriangleMesh m;
  m.positions = {{0, 0, -1}, {w, 0, -1}, {0, h, -1}, {0, 0, 1}, {w, 0, 1}, {0, h, 1}};
  m.triangles = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {0, 3, 5}, {0, 5, 2}, {1, 2, 5}, {1, 5, 4}};
  Scene s;
  s.source = "grazed wedge";
  s.objects.push_back({"wedge", "wedge", std::move(m)});
  s.light.type = LightType::Directional;
  s.light.position = {0.5 * width, height + 5.0, 0.0};
  s.light.direction = {0, -1, 0};
  s.light.halfExtent = width;
  s.light.nearPlane = 1.0;
  s.light.farPlane = height + 10.0;
  s.camera.eye = {0.0, 0.5 * height, 4.0 * height};
  s.camera.target = {0.0, 0.5 * height, 0.0};
  s.camera.nearPlane = 1.0;
  s.camera.farPlane = 8.0 * height;
  return s;
}

/// The spot light of the refinement tests: 50 degrees, from (0.6, 7, 0.4), tilted a little, near 1,
/// far 9.
inline Light refinementSpot() {
  Light light;
  light.type = LightType::Spot;
  light.position = {0.6, 7.0, 0.4};
  light.direction = glm::normalize(glm::dvec3(-0.1, -1.0, -0.05));
  light.fovYDegrees = 50.0;
  light.nearPlane = 1.0;
  light.farPlane = 9.0;
  return light;
}

}  // namespace shadowvol::test
