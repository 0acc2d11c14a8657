// libFuzzer harness for parseScene: any text is parsed into a scene or refused with InputError;
// a parsed scene has finite, fitted planes (near < far) and triangles whose indices are in range.
// Anything else (another exception, a crash, a sanitizer report, a hang) is a finding.
//
// Build and run: see fuzz_mesh_reader.cpp (target fuzz_scene_parser, corpus tests/fuzz/corpus/scene
// plus data/scenes). Mesh files named by a scene are looked up beside the working folder.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_check.h"
#include "shadowvol/error.h"
#include "shadowvol/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // A legal scene may hold 50 M triangles and take seconds to generate; the fuzzer's scenes are
    // capped at 20,000 (the same budget rule, a smaller budget) to keep executions short: with
    // 200,000 the corpus filled with heavy tessellations and ran at about 500 executions a second.
    const shadowvol::Scene s = shadowvol::parseScene(text, "fuzz.json", ".", 20'000).scene;
    fuzz::check(std::isfinite(s.light.nearPlane) && std::isfinite(s.light.farPlane) && s.light.farPlane > s.light.nearPlane,
                "fuzz_scene_parser", "light planes not fitted");
    fuzz::check(std::isfinite(s.camera.nearPlane) && s.camera.farPlane > s.camera.nearPlane, "fuzz_scene_parser", "camera planes not fitted");
    for (const auto& o : s.objects)
      for (const auto& t : o.mesh.triangles)
        for (const auto i : t) fuzz::check(i < o.mesh.positions.size(), "fuzz_scene_parser", "index out of range");
  } catch (const shadowvol::InputError&) {
    // refused with a message: fine
  }
  return 0;
}
