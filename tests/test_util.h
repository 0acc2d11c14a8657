// Helpers shared by the test folders.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "shadowvol/light.h"

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

inline std::filesystem::path sourceDir() { return SV_SOURCE_DIR; }

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

}  // namespace shadowvol::test
