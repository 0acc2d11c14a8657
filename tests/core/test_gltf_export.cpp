// glTF 2.0 export (mesh_io.h, lib/src/core/mesh_writers/gltf_writer.cpp), read back with an
// independent reader: tinygltf (Debian's libtinygltf-dev).
#include <cstring>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/primitives.h"
#include "test_util.h"

using namespace shadowvol;

namespace {

tinygltf::Model load(const std::filesystem::path& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = path.extension() == ".glb" || path.extension() == ".GLB";
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path.string())
                         : loader.LoadASCIIFromFile(&model, &err, &warn, path.string());
  EXPECT_TRUE(ok) << err;
  EXPECT_TRUE(warn.empty()) << warn;
  return model;
}

// The accessor's elements as bytes (tightly packed: the writer uses no byteStride).
template <class T>
std::vector<T> elements(const tinygltf::Model& m, int accessor, std::size_t perElement) {
  const tinygltf::Accessor& a = m.accessors.at(std::size_t(accessor));
  const tinygltf::BufferView& v = m.bufferViews.at(std::size_t(a.bufferView));
  const tinygltf::Buffer& b = m.buffers.at(std::size_t(v.buffer));
  std::vector<T> out(a.count * perElement);
  EXPECT_LE(v.byteOffset + a.byteOffset + out.size() * sizeof(T), b.data.size());
  std::memcpy(out.data(), b.data.data() + v.byteOffset + a.byteOffset, out.size() * sizeof(T));
  return out;
}

void expectSameMesh(const tinygltf::Model& m, const TriangleMesh& mesh, const glm::dvec3& origin) {
  ASSERT_EQ(m.scenes.size(), 1u);
  ASSERT_EQ(m.nodes.size(), 1u);
  if (origin == glm::dvec3(0.0)) {
    EXPECT_TRUE(m.nodes[0].translation.empty());
  } else {
    ASSERT_EQ(m.nodes[0].translation.size(), 3u);
    EXPECT_EQ(m.nodes[0].translation[0], origin.x);  // exact: the JSON carries 17 digits
    EXPECT_EQ(m.nodes[0].translation[1], origin.y);
    EXPECT_EQ(m.nodes[0].translation[2], origin.z);
  }
  ASSERT_EQ(m.meshes.size(), 1u);
  const tinygltf::Primitive& p = m.meshes[0].primitives.at(0);
  EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
  const tinygltf::Accessor& pos = m.accessors.at(std::size_t(p.attributes.at("POSITION")));
  EXPECT_EQ(pos.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(pos.type, TINYGLTF_TYPE_VEC3);
  const auto xyz = elements<float>(m, p.attributes.at("POSITION"), 3);
  ASSERT_EQ(xyz.size(), mesh.positions.size() * 3);
  for (std::size_t k = 0; k < mesh.positions.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(xyz[3 * k + c], mesh.positions[k][c]);
      EXPECT_GE(xyz[3 * k + c], pos.minValues.at(c));
      EXPECT_LE(xyz[3 * k + c], pos.maxValues.at(c));
    }
  EXPECT_EQ(m.accessors.at(std::size_t(p.indices)).componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  const auto idx = elements<std::uint32_t>(m, p.indices, 1);
  ASSERT_EQ(idx.size(), mesh.triangles.size() * 3);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(idx[3 * t + c], mesh.triangles[t][c]);
}

}  // namespace

TEST(GltfExport, BinaryAndJsonRoundTripThroughTinygltf) {
  const auto dir = test::tempDir();
  const TriangleMesh box = makeBox(1.5, 2.0, 0.25);
  for (const char* name : {"box.glb", "box.gltf", "BOX.GLB"}) {
    writeTriangleMesh(box, dir / name);
    expectSameMesh(load(dir / name), box, glm::dvec3(0.0));
  }
}

TEST(GltfExport, OriginBecomesTheNodeTranslation) {
  const auto dir = test::tempDir();
  const TriangleMesh box = makeBox(1, 1, 1);
  const glm::dvec3 origin(1e6 + 0.125, -3.0, 2.5e7 + 1.0 / 3.0);
  for (bool world : {false, true}) {
    writeTriangleMesh(box, dir / "far.glb", MeshFrame{origin, world});
    expectSameMesh(load(dir / "far.glb"), box, origin);
  }
}

TEST(GltfExport, EmptyMeshIsAValidSceneWithoutMesh) {
  const auto dir = test::tempDir();
  for (const char* name : {"empty.glb", "empty.gltf"}) {
    writeTriangleMesh(TriangleMesh{}, dir / name);
    const tinygltf::Model m = load(dir / name);
    ASSERT_EQ(m.nodes.size(), 1u);
    EXPECT_EQ(m.nodes[0].mesh, -1);
    EXPECT_TRUE(m.meshes.empty() && m.accessors.empty() && m.buffers.empty());
  }
}

TEST(GltfExport, GlbChunksAreAlignedAndLengthsAgree) {
  const auto dir = test::tempDir();
  writeTriangleMesh(makeBox(1, 1, 1), dir / "box.glb");
  std::ifstream in(dir / "box.glb", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GE(bytes.size(), 28u);
  auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_EQ(u32(4), 2u);
  EXPECT_EQ(u32(8), bytes.size());
  const std::uint32_t jsonLength = u32(12);
  EXPECT_EQ(jsonLength % 4, 0u);
  EXPECT_EQ(bytes.substr(16, 4), "JSON");
  const std::size_t bin = 20 + jsonLength;
  EXPECT_EQ(u32(bin) % 4, 0u);
  EXPECT_EQ(bytes.substr(bin + 4, 4), std::string("BIN\0", 4));
  EXPECT_EQ(bin + 8 + u32(bin), bytes.size());
  EXPECT_TRUE(isMeshOutputFormat("x.GLTF") && isMeshOutputFormat("x.glb") && !isMeshOutputFormat("x.fbx"));
}
