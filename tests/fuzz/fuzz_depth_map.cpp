// libFuzzer harness for readDepthMap followed by buildVolume: the input is a side file (JSON) and
// a PFM, separated by the first NUL byte. A map that reads must build into a volume with finite
// coordinates and in-range indices (or be refused by the builder with InputError).
//
// Build and run: see fuzz_mesh_reader.cpp (target fuzz_depth_map, corpus tests/fuzz/corpus/depth).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "fuzz_check.h"
#include "shadowvol/depth_map_io.h"
#include "shadowvol/error.h"
#include "shadowvol/volume_builder.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path dir = [] {
    // In memory where the system has it: the two files are written for every input.
    std::error_code ec;
    const auto base = std::filesystem::is_directory("/dev/shm", ec) ? std::filesystem::path("/dev/shm")
                                                                      : std::filesystem::temp_directory_path();
    auto d = base / ("shadowvol-fuzz-depth-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t cut = input.find('\0');
  if (cut == std::string::npos) return 0;
  const auto pfm = dir / "map.pfm";
  std::ofstream(shadowvol::depthSidecarPath(pfm), std::ios::binary | std::ios::trunc) << input.substr(0, cut);
  std::ofstream(pfm, std::ios::binary | std::ios::trunc) << input.substr(cut + 1);
  try {
    const shadowvol::DepthMap map = shadowvol::readDepthMap(pfm);
    if (map.depth.size() > 256 * 256) return 0;  // keep each execution short
    const shadowvol::VolumeBuildResult r = shadowvol::buildVolume(map, {});
    for (const auto& p : r.mesh.positions)
      fuzz::check(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "fuzz_depth_map", "non-finite volume vertex");
    for (const auto& t : r.mesh.triangles)
      for (const auto i : t) fuzz::check(i < r.mesh.positions.size(), "fuzz_depth_map", "index out of range");
  } catch (const shadowvol::InputError&) {
    // refused with a message: fine
  }
  return 0;
}
