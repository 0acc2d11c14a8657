#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <map>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <glm/geometric.hpp>

#include <nlohmann/json.hpp>

#include "shadowvol/depth_map_io.h"
#include "shadowvol/error.h"
#include "shadowvol/image_io.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/primitives.h"
#include "shadowvol/temporary_files.h"
#include "shadowvol/volume_builder.h"
#include "test_util.h"

namespace shadowvol {
namespace {

// Every directed edge once and its reverse once: closed and consistently oriented.
bool closedAndOriented(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : directed)
    if (n != 1 || directed.count({e.second, e.first}) != 1) return false;
  return !directed.empty();
}

double signedVolume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += glm::dot(glm::dvec3(m.positions[t[0]]),
                  glm::cross(glm::dvec3(m.positions[t[1]]), glm::dvec3(m.positions[t[2]]))) / 6.0;
  return v;
}

TEST(Primitives, ClosedOutwardAndOfTheRightVolume) {
  const double pi = 3.14159265358979323846;
  struct Case {
    const char* name;
    TriangleMesh mesh;
    double volume, tolerance;
  } cases[] = {
      {"box", makeBox(1, 2, 3), 6.0, 1e-6},
      {"icosphere", makeIcoSphere(1, 5), 4.0 / 3 * pi, 2e-3},
      {"uvsphere", makeUvSphere(1, 256, 128), 4.0 / 3 * pi, 2e-3},
      {"cylinder", makeCylinder(0.5, 2, 256), pi * 0.25 * 2, 1e-3},
      {"hemisphere", makeHemisphere(1, 256, 128), 2.0 / 3 * pi, 2e-3},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(closedAndOriented(c.mesh));
    EXPECT_NEAR(signedVolume(c.mesh), c.volume, c.tolerance * c.volume);  // > 0: outward
  }
  EXPECT_EQ(makeIcoSphere(1, 3).triangleCount(), 20u * 64);
  const TriangleMesh tree = makeTree(0.1, 2, 0.8, 2);
  EXPECT_GT(signedVolume(tree), 0.0);
}

TEST(Primitives, PlaneFacesUp) {
  const TriangleMesh p = makePlane(2, 4, 3);
  EXPECT_EQ(p.triangleCount(), 18u);
  for (const auto& t : p.triangles) {
    const glm::dvec3 n = glm::cross(glm::dvec3(p.positions[t[1]] - p.positions[t[0]]),
                                    glm::dvec3(p.positions[t[2]] - p.positions[t[0]]));
    EXPECT_GT(n.y, 0.0);
  }
}

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

TEST(MeshIo, EveryFormatReadsBackThroughOpenMesh) {
  const auto dir = test::tempDir();
  const TriangleMesh box = makeBox(1, 2, 3);
  for (const char* ext : {".ply", ".obj", ".off", ".stl"}) {
    SCOPED_TRACE(ext);
    const auto path = dir / (std::string("box") + ext);
    writeTriangleMesh(box, path);
    OMesh m;
    OpenMesh::IO::Options opt;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(m, path.string(), opt));
    EXPECT_EQ(m.n_faces(), 12u);
    const TriangleMesh back = readTriangleMesh(path);
    EXPECT_EQ(back.triangleCount(), 12u);
    EXPECT_NEAR(signedVolume(back), 6.0, 1e-5);
  }
  // No temporary files are left beside the outputs.
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

// Regression (far from the origin: exported PLY files got degenerate faces): without
// worldCoordinates the stored coordinates are written with the origin in the header; with it,
// PLY holds doubles and OBJ 17 digits, exactly stored + origin; STL refuses world coordinates.
TEST(MeshIo, OriginIsNamedOrWorldCoordinatesWrittenInDouble) {
  const auto dir = test::tempDir();
  const TriangleMesh box = makeBox(1, 2, 3);
  const MeshFrame local{{1e6, -2.5e5, 3.25}, false}, world{{1e6, -2.5e5, 3.25}, true};
  writeTriangleMesh(box, dir / "local.ply", local);
  writeTriangleMesh(box, dir / "local.obj", local);
  writeTriangleMesh(box, dir / "world.ply", world);
  writeTriangleMesh(box, dir / "world.obj", world);
  auto text = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_NE(text(dir / "local.ply").find("comment shadowvol origin 1000000 -250000 3.25"), std::string::npos);
  EXPECT_NE(text(dir / "local.obj").find("# shadowvol origin 1000000 -250000 3.25"), std::string::npos);
  const std::string ply = text(dir / "world.ply");
  const std::size_t body = ply.find("end_header\n");
  ASSERT_NE(body, std::string::npos);
  EXPECT_NE(ply.find("property double x"), std::string::npos);
  for (std::size_t k = 0; k < box.positions.size(); ++k) {
    glm::dvec3 p;
    std::memcpy(&p, ply.data() + body + 11 + k * sizeof p, sizeof p);
    EXPECT_EQ(p, glm::dvec3(box.positions[k]) + world.origin) << k;
  }
  std::istringstream obj(text(dir / "world.obj"));
  std::string tag;
  std::getline(obj, tag);
  for (std::size_t k = 0; k < box.positions.size(); ++k) {
    glm::dvec3 p;
    obj >> tag >> p.x >> p.y >> p.z;
    EXPECT_EQ(p, glm::dvec3(box.positions[k]) + world.origin) << k;
  }
  OMesh m;  // OpenMesh reads the double PLY back
  OpenMesh::IO::Options opt;
  EXPECT_TRUE(OpenMesh::IO::read_mesh(m, (dir / "world.ply").string(), opt));
  EXPECT_EQ(m.n_faces(), 12u);
  EXPECT_THROW(writeTriangleMesh(box, dir / "world.stl", world), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "world.stl"));
}

// Regression (an interrupted command left .tmp files beside its target): a process killed by
// SIGTERM while writing removes the temporary file; neither it nor the target remains.
TEST(MeshIo, KilledWhileWritingLeavesNothing) {
  const auto dir = test::tempDir();
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    removeTemporaryFilesOnSignal();
    writeAtomically(dir / "mesh.ply", [](const std::filesystem::path& tmp) {
      std::ofstream(tmp) << "half written";
      std::raise(SIGTERM);
    });
    std::_Exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// A fourteenth probe's finding: a command killed half-way through a several-file result (validate's
// report folder, render's image and stencil) left the files it had placed. Under an OutputSetGuard
// they go too; a file in place before the guard, and one written after it ends, stay.
TEST(MeshIo, KilledHalfWayThroughASetOfFilesLeavesNoneOfThem) {
  const auto dir = test::tempDir();
  test::writeText(dir / "older.txt", "kept");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    removeTemporaryFilesOnSignal();
    auto write = [&](const char* name) {
      writeAtomically(dir / name, [](const std::filesystem::path& tmp) { std::ofstream(tmp) << "whole"; });
    };
    {
      const OutputSetGuard done;
      write("finished.txt");
    }
    write("after.txt");
    const OutputSetGuard set;
    write("first.png");
    {
      const OutputSetGuard inner;  // nested (writeDepthMap's inside a command's): the outer set holds
      write("second.png");
    }
    std::raise(SIGTERM);
    std::_Exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_FALSE(std::filesystem::exists(dir / "first.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "second.png"));
  for (const char* kept : {"older.txt", "finished.txt", "after.txt"})
    EXPECT_TRUE(std::filesystem::exists(dir / kept)) << kept;
}

// Regression (a full disk left a truncated PNG in place and `render` exited 0: stbi_write_png does
// not report failed writes): with the file size limited (as a full disk would), every writer
// throws and leaves nothing. In a child process, with SIGXFSZ ignored so that writes fail EFBIG.
TEST(MeshIo, FailedWritesThrowAndLeaveNothing) {
  const auto dir = test::tempDir();
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) std::_Exit(2);
    std::vector<std::uint8_t> noise(256 * 256 * 3);  // incompressible: far above 4 KiB as a PNG
    std::uint32_t x = 12345;
    for (auto& b : noise) b = std::uint8_t((x = x * 1664525u + 1013904223u) >> 24);
    int thrown = 0;
    try {
      writePng(dir / "noise.png", 256, 256, 3, noise);
    } catch (const InputError&) {
      ++thrown;
    }
    try {
      writeTriangleMesh(makeIcoSphere(1.0, 5), dir / "sphere.ply");
    } catch (const InputError&) {
      ++thrown;
    }
    std::_Exit(thrown == 2 && std::filesystem::is_empty(dir) ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// What lies at the output path already: a pipe or device is refused, not replaced by a file (a
// probe's `--out` onto a FIFO; as root onto a device node); a symbolic link is written through; a
// read-only file is refused; a replaced file keeps its mode.
TEST(MeshIo, WritesRefuseDevicesAndReadOnlyFilesAndFollowLinks) {
  const auto dir = test::tempDir();
  const TriangleMesh box = makeBox(1, 1, 1);
  ASSERT_EQ(mkfifo((dir / "fifo.ply").c_str(), 0644), 0);
  EXPECT_THROW(writeTriangleMesh(box, dir / "fifo.ply"), InputError);
  EXPECT_EQ(std::filesystem::status(dir / "fifo.ply").type(), std::filesystem::file_type::fifo);
  test::writeText(dir / "real.ply", "old");
  std::filesystem::create_symlink("real.ply", dir / "link.ply");
  writeTriangleMesh(box, dir / "link.ply");
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.ply"));
  EXPECT_EQ(readTriangleMesh(dir / "real.ply").triangleCount(), 12u);
  std::filesystem::create_symlink("missing.ply", dir / "dangling.ply");
  EXPECT_THROW(writeTriangleMesh(box, dir / "dangling.ply"), InputError);
  test::writeText(dir / "private.ply", "old");
  std::filesystem::permissions(dir / "private.ply", std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  writeTriangleMesh(box, dir / "private.ply");
  EXPECT_EQ(std::filesystem::status(dir / "private.ply").permissions() & std::filesystem::perms::all,
            std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  // Refused also when run as root, who may write it (a twenty-second probe's finding), by its
  // permission bits; the file keeps what it held.
  test::writeText(dir / "ro.ply", "old");
  std::filesystem::permissions(dir / "ro.ply", std::filesystem::perms::owner_read);
  EXPECT_THROW(writeTriangleMesh(box, dir / "ro.ply"), InputError);
  EXPECT_EQ(test::readText(dir / "ro.ply"), "old");
}

TEST(MeshIo, UnknownExtensionWritesNothing) {
  const auto dir = test::tempDir();
  EXPECT_THROW(writeTriangleMesh(makeBox(1, 1, 1), dir / "box.xyz"), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  EXPECT_THROW(writeTriangleMesh(makeBox(1, 1, 1), dir / "missing-folder" / "box.ply"), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// A spot light at y = 5 looking straight down, near 1, far 9.
Light spotDown() {
  Light l;
  l.position = {0, 5, 0};
  l.direction = {0, -1, 0};
  l.nearPlane = 1;
  l.farPlane = 9;
  return l;
}

// Regression ("cannot write the file: Success"): a folder where the side file would go is named,
// and nothing is left beside it.
TEST(DepthMapIo, AFolderInTheSideFilesPlaceIsNamed) {
  const auto dir = test::tempDir();
  std::filesystem::create_directories(dir / "d.pfm.json");
  try {
    writeDepthMap(makeDepthMap(spotDown(), 4, 4, CaptureMode::Back), dir / "d.pfm");
    ADD_FAILURE() << "wrote over a folder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("d.pfm.json: is a folder"), std::string::npos) << e.what();
  }
  std::filesystem::remove(dir / "d.pfm.json");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(DepthMapIo, RoundTripsDepthsMatricesAndNoHit) {
  const auto dir = test::tempDir();
  const Light l = spotDown();
  DepthMap map = makeDepthMap(l, 5, 3, CaptureMode::Midpoint);
  for (std::size_t k = 0; k < map.depth.size(); ++k) map.depth[k] = k % 4 == 0 ? DepthMap::kNoHit : 1.0f + 0.5f * float(k);
  writeDepthMap(map, dir / "d.pfm");
  const DepthMap back = readDepthMap(dir / "d.pfm");
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.capture, CaptureMode::Midpoint);
  EXPECT_EQ(back.lightType, LightType::Spot);
  EXPECT_EQ(back.depth, map.depth);
  EXPECT_EQ(back.lightView, map.lightView);
  EXPECT_EQ(back.lightProjection, map.lightProjection);
  EXPECT_EQ(back.hitCount(), map.hitCount());
  EXPECT_EQ(back.origin, glm::dvec3(0.0));
  map.origin = {1e6, 2.5, -3e5};
  writeDepthMap(map, dir / "far.pfm");
  EXPECT_EQ(readDepthMap(dir / "far.pfm").origin, map.origin);
  EXPECT_EQ(readDepthMap(dir / "far.pfm").guard, 0);
  // The guard band (light.h) travels with the map; one that leaves no 2 x 2 window is not written.
  DepthMap banded = makeDepthMap(spotDown(), 6, 6, CaptureMode::Back);
  banded.guard = 2;
  writeDepthMap(banded, dir / "band.pfm");
  EXPECT_EQ(readDepthMap(dir / "band.pfm").guard, 2);
  map.guard = 1;  // 5 x 3
  EXPECT_THROW(writeDepthMap(map, dir / "bad.pfm"), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.pfm"));
}

// Regression (non-finite output with exit 0): a side file with a singular or non-rigid lightView,
// a projection of the wrong kind or with 1e300 entries, far 1e300 or an origin beyond a scene's
// +-1e12 is refused, its field named.
TEST(DepthMapIo, SideFilesWithUnusableMatricesAreRefused) {
  const auto dir = test::tempDir();
  const Light l = spotDown();
  writeDepthMap(makeDepthMap(l, 4, 4, CaptureMode::Back), dir / "d.pfm");
  const auto side = depthSidecarPath(dir / "d.pfm");
  std::string good;
  {
    std::ifstream in(side);
    good.assign(std::istreambuf_iterator<char>(in), {});
  }
  auto expectRefused = [&](const std::string& key, const std::string& replacement, const std::string& field) {
    SCOPED_TRACE(key + " -> " + replacement);
    nlohmann::json j = nlohmann::json::parse(good);
    j[key] = nlohmann::json::parse(replacement);
    test::writeText(side, j.dump());
    try {
      readDepthMap(dir / "d.pfm");
      FAIL() << "accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  expectRefused("lightView", "[0,0,0,0, 0,0,0,0, 0,0,0,0, 0,0,0,1]", "/lightView");
  expectRefused("lightView", "[2,0,0,0, 0,2,0,0, 0,0,2,0, 0,0,0,1]", "/lightView");
  expectRefused("lightView", "[1,0,0,0, 0,1,0,0, 0,0,1,0, 1e300,0,0,1]", "/lightView");
  expectRefused("lightProjection", "[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]", "/lightProjection");
  expectRefused("lightProjection", "[1,0,0,0, 0,1,0,0, 0,0,1e300,-1, 0,0,1e300,0]", "/lightProjection");
  // Regression (fuzz_depth_map): a w row that varies with x passed the kind check, and the builder
  // put texels at infinity; entries the unprojection does not read must be 0.
  for (int entry : {1, 2, 3, 4, 6, 7}) {
    nlohmann::json p = nlohmann::json::parse(good)["lightProjection"];
    p[entry] = 0.5;
    expectRefused("lightProjection", p.dump(), "/lightProjection");
  }
  // A second probe's findings: a spot narrower than a scene's may be, and a light far from the
  // side file's origin, built volumes that collapsed in single precision.
  {
    nlohmann::json p = nlohmann::json::parse(good)["lightProjection"];
    p[0] = p[0].get<double>() * 1e8;
    p[5] = p[5].get<double>() * 1e8;
    expectRefused("lightProjection", p.dump(), "/lightProjection");
    nlohmann::json v = nlohmann::json::parse(good)["lightView"];
    v[12] = v[12].get<double>() + 1e11;
    expectRefused("lightView", v.dump(), "/lightView");
  }
  expectRefused("far", "1e300", "/far");
  expectRefused("near", "-1", "/near");
  expectRefused("origin", "[1, 2]", "/origin");
  expectRefused("origin", "[1e300, 0, 0]", "/origin");  // regression: written out as 1e300 (inf in glTF)
  expectRefused("origin", "[0, 0, -2e12]", "/origin");
  // The guard band: whole texels, at most kMaxGuardTexels, leaving a 2 x 2 window (this map is 4 x 4).
  expectRefused("guard", "-1", "/guard");
  expectRefused("guard", "2", "/guard");
  expectRefused("guard", "1.5", "/guard");
  expectRefused("guard", "\"1\"", "/guard");
  // A third probe's findings: a height that did not match was named as /width; an unknown key, a
  // format of another version and a checksum that is not a string or of another algorithm passed or
  // were named vaguely; a key given twice was blamed on the matrix after it.
  expectRefused("height", "32", "/height");
  expectRefused("comment", "\"hi\"", "/comment");
  expectRefused("format", "\"shadowvol depth map 2\"", "/format");
  expectRefused("depthChecksum", "12", "/depthChecksum");
  expectRefused("depthChecksum", "\"sha256:abcd\"", "/depthChecksum");
  // A thirteenth probe's: a width given as a string was called a mismatch, 4.0 for a whole number was
  // taken (the scene files refuse it), and a quantity of another kind passed without a word.
  expectRefused("width", "\"4\"", "/width");
  expectRefused("width", "4.0", "/width");
  expectRefused("writer", "5", "/writer");
  expectRefused("quantity", "\"NDC z\"", "/quantity");
  {
    std::string twice = good;
    twice.insert(twice.find('{') + 1, "\"near\": 1.0, ");
    test::writeText(side, twice);
    try {
      readDepthMap(dir / "d.pfm");
      FAIL() << "accepted a key twice";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("a key given twice"), std::string::npos) << e.what();
    }
  }
  test::writeText(side, good);
  EXPECT_NO_THROW(readDepthMap(dir / "d.pfm"));
}

TEST(DepthMapIo, BadFilesAreRefusedWithTheirName) {
  const auto dir = test::tempDir();
  auto expectError = [&](const std::string& name, const std::string& phrase) {
    try {
      readDepthMap(dir / name);
      FAIL() << name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    }
  };
  expectError("none.pfm", "cannot open");
  test::writeText(dir / "rgb.pfm", "PF\n2 2\n-1.0\n");
  expectError("rgb.pfm", "Pf");
  test::writeText(dir / "short.pfm", "Pf\n4 4\n-1.0\n0123");
  expectError("short.pfm", "shorter");
  // Regressions (a hostile-input probe): data beyond the header's size was read as if absent (a
  // header of 8 x 8 over 16 x 16 depths built from the wrong texels), and a CR LF header shifted
  // the depths by a byte and was reported as a bad depth.
  test::writeText(dir / "long.pfm", "Pf\n1 1\n-1.0\n" + std::string(8, '\0'));
  expectError("long.pfm", "4 bytes after the header's 4 bytes of depths");
  test::writeText(dir / "crlf.pfm", "Pf\r\n1 1\r\n-1.0\r\n" + std::string(4, '\0'));
  expectError("crlf.pfm", "CR LF");
  test::writeText(dir / "nan.pfm", "Pf\n1 1\nnan\n" + std::string(4, '\0'));  // once "bad PFM size"
  expectError("nan.pfm", "header scale = nan");
  // The size is quoted as written (a twelfth probe's finding: 4294967297 1 was quoted as 2147483647x0).
  test::writeText(dir / "huge.pfm", "Pf\n4294967297 1\n-1.0\n" + std::string(4, '\0'));
  expectError("huge.pfm", "header = 4294967297 1: bad PFM size");
  test::writeText(dir / "frac.pfm", "Pf\n2.5 1\n-1.0\n" + std::string(8, '\0'));
  expectError("frac.pfm", "header = 2.5 1: bad PFM size");
  test::writeText(dir / "long-size.pfm", "Pf\n1234567890123456789012345 1\n-1.0\n");  // cut at 24, said so
  expectError("long-size.pfm", "header = 123456789012345678901234... 5: bad PFM size");
  // A good PFM without its side file.
  Light l;
  l.nearPlane = 1;
  l.farPlane = 2;
  writeDepthMap(makeDepthMap(l, 2, 2, CaptureMode::Back), dir / "ok.pfm");
  // A side file with a NUL byte after its JSON (the JSON lexer took it for the end of the input).
  std::ofstream(depthSidecarPath(dir / "ok.pfm"), std::ios::binary | std::ios::app) << std::string(1, '\0') << "{garbage";
  expectError("ok.pfm", "NUL byte");
  std::filesystem::remove(depthSidecarPath(dir / "ok.pfm"));
  expectError("ok.pfm", "side file");
}

// Regression (an interrupted `depth` could leave a new side file beside an old PFM, and `build`
// then used mismatched data with exit 0): the side file's checksum of the depths must match.
TEST(DepthMapIo, SideFileOfAnotherDepthMapIsRefused) {
  const auto dir = test::tempDir();
  Light l;
  l.nearPlane = 1;
  l.farPlane = 2;
  DepthMap a = makeDepthMap(l, 3, 3, CaptureMode::Back), b = a;
  b.depth[4] = 1.5f;
  writeDepthMap(a, dir / "a.pfm");
  writeDepthMap(b, dir / "b.pfm");
  std::filesystem::copy_file(depthSidecarPath(dir / "b.pfm"), depthSidecarPath(dir / "a.pfm"),
                             std::filesystem::copy_options::overwrite_existing);
  try {
    readDepthMap(dir / "a.pfm");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "/depthChecksum") << e.what();
  }
  EXPECT_EQ(readDepthMap(dir / "b.pfm").depth, b.depth);
}

// The depth-map fuzz harness's corpus (tests/fuzz/corpus/depth: a side file, a NUL, a PFM; seeds
// and the inputs fuzzing found), replayed as the harness does: each is refused with InputError or
// reads and builds into a finite, in-range volume. regression-projective-w.bin is refused (its
// projection's w varied with x; the volume had non-finite vertices).
TEST(DepthMapIo, FuzzCorpusReplaysThroughTheBuilder) {
  const auto dir = test::tempDir();
  int files = 0, refused = 0;
  for (const auto& e : std::filesystem::directory_iterator(test::sourceDir() / "tests/fuzz/corpus/depth")) {
    SCOPED_TRACE(e.path().string());
    std::ifstream in(e.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const std::size_t cut = bytes.find('\0');
    ASSERT_NE(cut, std::string::npos);
    test::writeText(depthSidecarPath(dir / "map.pfm"), bytes.substr(0, cut));
    test::writeText(dir / "map.pfm", bytes.substr(cut + 1));
    VolumeBuildResult r;
    try {
      r = buildVolume(readDepthMap(dir / "map.pfm"), {});
    } catch (const InputError&) {
      EXPECT_NE(e.path().filename().string().find("regression"), std::string::npos) << "a seed was refused";
      ++refused;
      continue;
    }
    EXPECT_GT(r.mesh.triangleCount(), 0u);
    for (const auto& p : r.mesh.positions) ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    for (const auto& t : r.mesh.triangles)
      for (auto i : t) ASSERT_LT(i, r.mesh.positions.size());
    ++files;
  }
  EXPECT_GE(refused, 1);
  EXPECT_GE(files, 2);
}

// Regression (a PFM header of 46341^2 allocated 8 GB before the data length was checked; /dev/zero
// read as a PFM ran for a minute): the length is checked first, and devices are refused.
TEST(DepthMapIo, HugeHeadersAndDevicesAreRefusedBeforeAllocating) {
  const auto dir = test::tempDir();
  test::writeText(dir / "huge.pfm", "Pf\n46341 46341\n-1.0\n0123");
  try {
    readDepthMap(dir / "huge.pfm");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shorter"), std::string::npos) << e.what();
  }
  try {
    readDepthMap("/dev/zero");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace shadowvol
