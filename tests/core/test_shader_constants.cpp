// The GLSL mirrors' constants against the C++ ones they copy (the shaders cannot include a C++
// header): read from the shader sources, so that a change on one side fails here.
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/crossing_snap.h"
#include "test_util.h"

namespace shadowvol {
namespace {

std::string shaderText(const std::string& name) {
  std::ifstream in(test::sourceDir() / "shaders" / name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The value of `const <type> <name> = <value>;` in the shader, as written.
std::string constantOf(const std::string& text, const std::string& name) {
  std::smatch m;
  const std::regex re("const\\s+\\w+\\s+" + name + "\\s*=\\s*([^;]+);");
  return std::regex_search(text, m, re) ? m[1].str() : std::string();
}

TEST(ShaderConstants, SnapConstantsMatchTheShader) {
  const std::string rays = shaderText("silhouette_rays.comp");
  ASSERT_FALSE(rays.empty());
  EXPECT_EQ(std::stoi(constantOf(rays, "kSnapRounds")), kSnapRounds);
  const std::string probe = constantOf(rays, "kSnapProbeTexels");
  std::smatch m;
  ASSERT_TRUE(std::regex_match(probe, m, std::regex("1\\.0\\s*/\\s*([0-9.]+)"))) << probe;
  EXPECT_EQ(1.0 / std::stod(m[1].str()), kSnapProbeTexels);
  EXPECT_EQ(std::stod(constantOf(rays, "kSnapEndSlack")), kSnapEndSlack);
}

// The value of `<name> = <digits>u` in the shader (one of several uints declared on one line).
long uintOf(const std::string& text, const std::string& name) {
  std::smatch m;
  return std::regex_search(text, m, std::regex("\\b" + name + "\\s*=\\s*([0-9]+)u")) ? std::stol(m[1].str()) : -1;
}

TEST(ShaderConstants, BoundaryFlagBitsMatchTheShader) {
  const std::string common = shaderText("refine_common.glsl");
  ASSERT_FALSE(common.empty());
  EXPECT_EQ(uintOf(common, "kBoundaryBit"), long(kFlagBoundary));
  EXPECT_EQ(uintOf(common, "kNearAtPBit"), long(kFlagNearAtP));
  EXPECT_EQ(uintOf(common, "kSurfaceBit"), long(kFlagSurface));
}

}  // namespace
}  // namespace shadowvol
