// The EGL context, shader loading and error reporting.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <sys/wait.h>
#include <unistd.h>

#include "gl_test_support.h"
#include "shadowvol/error.h"
#include "shadowvol/gl/gl_error.h"
#include "shadowvol/image_io.h"
#include "shadowvol/gl/shader_program.h"

using namespace shadowvol;

TEST(GlContext, ReportsPlatformAndDriver) {
  const gl::ContextInfo& info = gltest::sharedRenderer().info();
  EXPECT_TRUE(info.platform == "device" || info.platform == "surfaceless" || info.platform == "default");
  EXPECT_FALSE(info.glVendor.empty());
  EXPECT_FALSE(info.glRenderer.empty());
  EXPECT_FALSE(info.glVersion.empty());
  EXPECT_GE(info.glMajor * 10 + info.glMinor, 33);
  EXPECT_FALSE(info.attempts.empty());
  std::printf("EGL platform %s (%s), %s / %s / %s\n", info.platform.c_str(), info.device.c_str(), info.glVendor.c_str(),
              info.glRenderer.c_str(), info.glVersion.c_str());
}

/// Runs `f`, which must throw an InputError naming `source` and `field` (the library's own terms,
/// never a command-line flag: the CLI maps them, apps/shadowvol/cli_errors.cpp).
template <class F>
void expectInputError(F&& f, const std::string& source, const std::string& field) {
  try {
    f();
    ADD_FAILURE() << "no InputError for " << source << " " << field;
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), source) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_EQ(std::string(e.what()).find("--"), std::string::npos) << e.what();
  }
}

// A fifteenth probe's finding: a process forked after its parent used GL (Python multiprocessing's
// fork start method) drew nothing on its first frame and a validation FAILED a right method. Such
// a child is refused GL with the reason and the way out; the parent goes on.
TEST(GlContext, AChildForkedAfterGlUseIsRefusedGl) {
  gltest::sharedRenderer();  // this process has used GL
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    int code = 1;
    try {
      gl::Renderer r{gl::RendererOptions{}};
    } catch (const gl::GlError& e) {
      const std::string what = e.what();
      code = what.find("forked") != std::string::npos && what.find("'spawn'") != std::string::npos ? 0 : 2;
    } catch (...) {
      code = 3;
    }
    std::_Exit(code);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: GL was given to the child; 2: another message; 3: another error";
  gl::Renderer again{gl::RendererOptions{}};  // the parent itself still may
  EXPECT_FALSE(again.info().glRenderer.empty());
}

TEST(GlContext, UnknownPlatformIsAnInputError) {
  gl::RendererOptions o;
  o.context.platform = "wayland";
  expectInputError([&] { gl::Renderer r{o}; }, "ContextOptions", "platform");
}

TEST(GlContext, EveryPlatformEitherWorksOrThrowsGlError) {
  for (const char* p : {"device", "surfaceless", "default"}) {
    gl::RendererOptions o;
    o.context.platform = p;
    try {
      gl::Renderer r(o);
      EXPECT_EQ(r.info().platform, p);
    } catch (const gl::GlError& e) {
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
    }
  }
}

TEST(GlShaders, EmbeddedSourcesArePresent) {
  for (const char* name : {"light.vert", "version_330.glsl", "version_430.glsl", "blur.frag"}) {
    auto text = gl::embeddedShader(name);
    ASSERT_TRUE(text.has_value()) << name;
    EXPECT_NE(text->find("#version"), std::string::npos) << name;
  }
  // volume_common.glsl and the stage bodies after it carry no #version of their own (a
  // version_*.glsl file comes first).
  for (const char* name : {"resolve.frag", "scene.frag", "paraboloid.glsl", "light_paraboloid.vert", "light_paraboloid.geom", "light_window_depth.glsl", "volume_common.glsl", "volume_gpu.geom", "volume_keep.geom",
                           "volume_mesh.comp", "volume_index.frag", "volume_index.vert", "light_mark.frag",
                           "light_mark.glsl", "light_triangle.glsl", "refine_common.glsl", "boundary_edges.comp",
                           "volume_refined.comp", "volume_refined.vert"}) {
    auto text = gl::embeddedShader(name);
    ASSERT_TRUE(text.has_value()) << name;
    EXPECT_EQ(text->find("#version"), std::string::npos) << name;
  }
  EXPECT_FALSE(gl::embeddedShader("no_such.frag").has_value());
}

TEST(GlShaders, OverrideDirectoryReplacesAFileAndCompileErrorsNameIt) {
  const auto dir = std::filesystem::temp_directory_path() / "shadowvol_shader_override_test";
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "blur.frag");
    f << "#version 330 core\nvoid main() { this is not glsl; }\n";
  }
  gl::ShaderLibrary lib(dir);
  EXPECT_EQ(lib.load("blur.frag").second, (dir / "blur.frag").string());
  EXPECT_NE(lib.load("light.vert").second.find("embedded"), std::string::npos);
  gl::RendererOptions o;
  o.shaderDir = dir;
  try {
    gl::Renderer r(o);
    FAIL() << "a broken shader must not compile";
  } catch (const gl::GlError& e) {
    EXPECT_NE(std::string(e.what()).find("blur.frag"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("compile failed"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
  // Regression (a misspelt SHADOWVOL_SHADER_DIR silently meant the embedded shaders): a folder
  // that is not there is refused, named.
  EXPECT_THROW(gl::ShaderLibrary(dir / "missing"), InputError);
  const char* was = std::getenv("SHADOWVOL_SHADER_DIR");
  const std::string saved = was ? was : "";
  ASSERT_EQ(setenv("SHADOWVOL_SHADER_DIR", (dir / "missing").c_str(), 1), 0);
  try {
    gl::ShaderLibrary fromEnvironment{std::filesystem::path()};
    ADD_FAILURE() << "accepted a missing folder";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "SHADOWVOL_SHADER_DIR") << e.what();
  }
  if (was) setenv("SHADOWVOL_SHADER_DIR", saved.c_str(), 1);
  else unsetenv("SHADOWVOL_SHADER_DIR");
}

TEST(GlRenderer, RejectsBadSizesAndMissingScene) {
  {
    gl::Renderer fresh;
    EXPECT_THROW(fresh.render(gl::RenderOptions{}), InputError);
    EXPECT_THROW(fresh.captureDepth(32, 32, CaptureMode::Back), InputError);
    Scene unfitted = defaultScene();
    unfitted.camera.nearPlane = unfitted.camera.farPlane = 0.0;
    EXPECT_THROW(fresh.setScene(unfitted), InputError);
  }
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(defaultScene());
  expectInputError([&] { r.captureDepth(1, 64, CaptureMode::Back); }, "Renderer::captureDepth", "width x height");
  expectInputError([&] { r.captureDepth(64, 1 << 20, CaptureMode::Back); }, "Renderer::captureDepth", "width x height");
  gl::RenderOptions o;
  o.imageWidth = -3;
  expectInputError([&] { r.render(o); }, "RenderOptions", "imageWidth x imageHeight");
  o = {};
  o.depthWidth = 1;
  expectInputError([&] { r.render(o); }, "RenderOptions", "depthWidth x depthHeight");
  o = {};
  o.shadowBiasSlope = std::nan("");
  expectInputError([&] { r.render(o); }, "RenderOptions", "shadowBiasSlope");
  o = {};
  o.volumeOptions.refineSteps = 2;  // the refined GPU volume walks one layer: not midpoint
  o.capture = CaptureMode::Midpoint;
  expectInputError([&] { r.render(o); }, "RenderOptions", "volumeOptions.refineSteps");
}

TEST(GlImageIo, PngRoundTripKeepsRowsTopFirst) {
  const auto path = std::filesystem::temp_directory_path() / "shadowvol_png_roundtrip.png";
  std::vector<std::uint8_t> px = {10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255, 1, 2, 3, 4};
  writePng(path, 2, 2, 4, px);
  const Image8 img = readPng(path);
  EXPECT_EQ(img.width, 2);
  EXPECT_EQ(img.height, 2);
  EXPECT_EQ(img.channels, 4);
  EXPECT_EQ(img.pixels, px);
  std::filesystem::remove(path);
  EXPECT_THROW(writePng("/nonexistent_dir/x.png", 2, 2, 4, px), InputError);
  EXPECT_THROW(readPng("/nonexistent_dir/x.png"), InputError);
}

// No EGL driver at all (glvnd pointed at a vendor file that does not exist): the renderer throws
// GlError listing every platform it tried instead of crashing. Runs in a fresh process (threadsafe
// death-test style re-executes the test binary) so EGL is not yet initialised there.
TEST(GlContextDeathTest, NoEglDriverIsAClearError) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/shadowvol_no_egl_vendor.json", 1);
        try {
          gl::Renderer r;
          std::exit(4);
        } catch (const gl::GlError& e) {
          std::fprintf(stderr, "%s\n", e.what());
          std::exit(3);
        }
      },
      ::testing::ExitedWithCode(3), "no headless OpenGL >= 3.3 core context through EGL");
}
