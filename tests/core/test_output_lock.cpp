// OutputLock (output_lock.h): one run at a time writes a several-file result into a folder (a
// fourteenth probe's finding: two runs given one report folder left the report of one beside the
// images of the other, and two `depth` runs a map beside the other's side file).
#include <chrono>
#include <string>
#include <thread>

#include <glm/mat4x4.hpp>
#include <gtest/gtest.h>

#include "shadowvol/depth_map.h"
#include "shadowvol/depth_map_io.h"
#include "shadowvol/error.h"
#include "shadowvol/output_lock.h"
#include "test_util.h"

namespace shadowvol {
namespace {

using std::chrono::milliseconds;

TEST(OutputLock, AFolderHeldByAnotherRunIsRefusedNamedAndTakenOnceFree) {
  const auto dir = test::tempDir();
  {
    const test::FolderHeldElsewhere other(dir);
    ASSERT_TRUE(other.holding());
    try {
      const OutputLock lock(dir, milliseconds(0));
      FAIL() << "locked a folder another process holds";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(dir.string()), std::string::npos) << what;
      EXPECT_NE(what.find("another run holds this folder"), std::string::npos) << what;
    }
  }
  // The library's own set of files, a depth map and its side file, waits for the folder: nothing
  // is written while another run holds it, the whole set once it lets go.
  DepthMap map;
  map.width = map.height = 2;
  map.depth.assign(4, 1.0f);
  map.nearPlane = 0.5, map.farPlane = 2.0;
  map.lightProjection = glm::dmat4(1.0);
  {
    test::FolderHeldElsewhere other(dir);
    ASSERT_TRUE(other.holding());
    std::thread writer([&] { writeDepthMap(map, dir / "d.pfm"); });
    std::this_thread::sleep_for(milliseconds(300));
    EXPECT_FALSE(std::filesystem::exists(dir / "d.pfm"));  // written while the other run held the folder
    other.release();
    writer.join();
    EXPECT_TRUE(std::filesystem::exists(dir / "d.pfm") && std::filesystem::exists(dir / "d.pfm.json"));
  }
  const OutputLock free(dir, milliseconds(0));  // released when the other process let go
  const OutputLock nested(dir, milliseconds(0));  // this thread holds it: no wait for itself
  SUCCEED();
}

TEST(OutputLock, TwoThreadsTakeTurns) {
  const auto dir = test::tempDir();
  const OutputLock mine(dir, milliseconds(0));
  bool refused = false;
  std::thread([&] {
    try {
      const OutputLock theirs(dir, milliseconds(0));
    } catch (const InputError&) {
      refused = true;
    }
  }).join();
  EXPECT_TRUE(refused);
}

TEST(OutputLock, AMissingFolderIsNamed) {
  const auto dir = test::tempDir() / "missing";
  try {
    const OutputLock lock(dir);
    FAIL() << "locked a missing folder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace shadowvol
