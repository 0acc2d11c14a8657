// libFuzzer harness for the mesh readers: each input is parsed in memory as every format (.obj,
// .off, .ply, .stl) by parseTriangleMesh, the code readTriangleMesh runs on a file's bytes.
// Reading must end in a mesh whose indices are in range and whose coordinates are finite, or in
// InputError; anything else (another exception, a crash, a sanitizer report, a hang, an
// allocation beyond -rss_limit_mb) is a finding.
//
// Build (Clang): cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang
//   -DSHADOWVOL_FUZZ=ON -DSHADOWVOL_BUILD_TESTS=OFF -DSHADOWVOL_BUILD_BENCHMARKS=OFF -DSHADOWVOL_BUILD_GL=OFF
//   && ninja -C build-fuzz fuzz_mesh_reader fuzz_scene_parser fuzz_depth_map
// Run:   build-fuzz/tests/fuzz/fuzz_mesh_reader -runs=10000000 -rss_limit_mb=2048 -malloc_limit_mb=500
//          -timeout=30 /tmp/mesh-corpus tests/fuzz/corpus/mesh   (README "Fuzzing" says why these limits)
// (likewise fuzz_scene_parser with tests/fuzz/corpus/scene, fuzz_depth_map with .../depth)
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "fuzz_check.h"
#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (const char* ext : {".obj", ".off", ".ply", ".stl"}) {
    try {
      const shadowvol::TriangleMesh mesh = shadowvol::parseTriangleMesh(bytes, ext, std::string("input") + ext);
      fuzz::check(!mesh.triangles.empty(), "fuzz_mesh_reader", "a mesh without triangles was returned");
      for (const auto& p : mesh.positions)
        fuzz::check(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "fuzz_mesh_reader", "non-finite position");
      for (const auto& t : mesh.triangles)
        for (const auto i : t) fuzz::check(i < mesh.positions.size(), "fuzz_mesh_reader", "index out of range");
    } catch (const shadowvol::InputError&) {
      // refused with a message: fine
    }
  }
  return 0;
}
