// Compressed and quantized geometry (gltf_compression.hpp): BoxTextured as gltfpack compresses it
// (EXT_meshopt_compression + KHR_mesh_quantization) and as draco_transcoder does
// (KHR_draco_mesh_compression) loads to the same box as the uncompressed file, within what the
// quantization moves; broken streams are one error naming the view or the primitive. (The images
// they render are compared in tests/cli/gltf_inputs_test.cpp.)

#include "gltf_support.hpp"

#include <glm/geometric.hpp>

#include <cstring>
#include <limits>

namespace luxel::scenes::test {
namespace {

/// A .glb's JSON and binary chunk.
struct GlbParts {
  json doc;
  std::vector<uint8_t> bin;
};

GlbParts split_glb(const std::string& path) {
  const std::vector<uint8_t> b = read_bytes(path);
  uint32_t json_length, bin_length = 0;
  std::memcpy(&json_length, b.data() + 12, 4);
  GlbParts parts;
  parts.doc = json::parse(b.begin() + 20, b.begin() + 20 + json_length);
  const size_t bin_at = 20 + json_length;
  if (bin_at + 8 <= b.size()) {
    std::memcpy(&bin_length, b.data() + bin_at, 4);
    parts.bin.assign(b.begin() + long(bin_at) + 8, b.begin() + long(bin_at) + 8 + bin_length);
  }
  return parts;
}

void write_glb_parts(const std::string& path, const GlbParts& parts) {
  std::string text = parts.doc.dump();
  while (text.size() % 4) text += ' ';
  std::vector<uint8_t> bin = parts.bin;
  while (bin.size() % 4) bin.push_back(0);
  std::vector<uint8_t> out;
  auto u32 = [&](uint32_t v) { out.insert(out.end(), reinterpret_cast<uint8_t*>(&v), reinterpret_cast<uint8_t*>(&v) + 4); };
  u32(0x46546C67u), u32(2), u32(uint32_t(12 + 8 + text.size() + 8 + bin.size()));
  u32(uint32_t(text.size())), u32(0x4E4F534Au);
  out.insert(out.end(), text.begin(), text.end());
  u32(uint32_t(bin.size())), u32(0x004E4942u);
  out.insert(out.end(), bin.begin(), bin.end());
  write_bytes(path, out);
}

const std::string kOriginalBox = "box-textured/glTF-Binary/BoxTextured.glb";
const std::string kMeshoptBox = "box-textured/glTF-meshopt/BoxTextured.glb";
const std::string kDracoBox = "box-textured/glTF-Draco/BoxTextured.glb";

/// The largest distance from a vertex of `decoded` to the nearest vertex of `original` with the
/// same normal (to within 0.05) and UV (to within 0.01): position, normal and UV errors.
struct VertexErrors { float position = 0, normal = 0, uv = 0; };
VertexErrors nearest_vertex_errors(const Mesh& original, const Mesh& decoded) {
  VertexErrors e;
  for (size_t v = 0; v < decoded.positions.size(); ++v) {
    float best = std::numeric_limits<float>::infinity();
    size_t match = 0;
    for (size_t o = 0; o < original.positions.size(); ++o) {
      const float d = glm::length(original.positions[o] - decoded.positions[v]) + 100.0f * glm::length(original.normals[o] - decoded.normals[v]) +
                      100.0f * glm::length(original.uv0[o] - decoded.uv0[v]);
      if (d < best) best = d, match = o;
    }
    e.position = std::max(e.position, glm::length(original.positions[match] - decoded.positions[v]));
    e.normal = std::max(e.normal, glm::length(original.normals[match] - decoded.normals[v]));
    e.uv = std::max(e.uv, glm::length(original.uv0[match] - decoded.uv0[v]));
  }
  return e;
}

void expect_same_box(const std::string& compressed, float position_tolerance, float normal_tolerance, float uv_tolerance) {
  const Scene original = load_gltf(asset(kOriginalBox), no_defaults());
  const Scene decoded = load_gltf(asset(compressed), no_defaults());
  ASSERT_EQ(decoded.meshes.size(), 1u);
  const Mesh& a = original.meshes[0];
  Mesh b = decoded.meshes[0];
  // gltfpack's quantized UVs are dequantized by a texture transform (KHR_texture_transform).
  const TextureRef& base = decoded.materials[0].base;
  ASSERT_EQ(base.rotation, 0.0f);
  for (glm::vec2& uv : b.uv0) uv = uv * base.scale + base.offset;
  EXPECT_EQ(b.triangle_count(), a.triangle_count());
  EXPECT_EQ(b.positions.size(), a.positions.size());
  ASSERT_EQ(b.normals.size(), b.positions.size());
  ASSERT_EQ(b.uv0.size(), b.positions.size());
  const VertexErrors e = nearest_vertex_errors(a, b);
  EXPECT_LE(e.position, position_tolerance) << compressed;
  EXPECT_LE(e.normal, normal_tolerance) << compressed;
  EXPECT_LE(e.uv, uv_tolerance) << compressed;
  // Every triangle keeps its winding: its face normal agrees with its vertices' normals.
  for (size_t t = 0; t < b.triangle_count(); ++t) {
    const glm::vec3 p0 = b.positions[b.vertex_of_corner(3 * t)], p1 = b.positions[b.vertex_of_corner(3 * t + 1)],
                    p2 = b.positions[b.vertex_of_corner(3 * t + 2)];
    EXPECT_GT(glm::dot(glm::cross(p1 - p0, p2 - p0), b.normals[b.vertex_of_corner(3 * t)]), 0.0f) << compressed << " triangle " << t;
  }
  EXPECT_EQ(decoded.materials.size(), original.materials.size());
  EXPECT_EQ(decoded.textures.size(), original.textures.size());
}

// The box is 1 m = 39.37 inches on a side. 14-bit positions: a step of 1/16383 of the side, half of
// it at most, 0.0012 inches; 8-bit octahedral normals (meshopt) and 10-bit ones (Draco) within a
// few hundredths; 12-bit UVs within a few 1/4095 steps of their range (the box's UVs span more
// than one texture width).
TEST(GltfCompression, MeshoptAndQuantizationDecodeToTheSameBox) {
  expect_same_box(kMeshoptBox, 0.0013f, 0.02f, 0.001f);
}

TEST(GltfCompression, DracoDecodesToTheSameBox) {
  expect_same_box(kDracoBox, 0.0025f, 0.01f, 0.002f);
}

TEST(GltfCompression, ABrokenMeshoptStreamIsNamed) {
  TempDir dir;
  GlbParts parts = split_glb(asset(kMeshoptBox));
  json& ext = parts.doc["bufferViews"][2]["extensions"]["EXT_meshopt_compression"];
  ext["byteLength"] = ext["byteLength"].get<int>() - 20;
  const std::string truncated = dir.file("truncated.glb");
  write_glb_parts(truncated, parts);
  expect_gltf_error(truncated, "bufferViews[2].extensions.EXT_meshopt_compression: the ATTRIBUTES stream does not decode", [&] {
    load_gltf(truncated);
  });

  GlbParts stride = split_glb(asset(kMeshoptBox));
  stride.doc["bufferViews"][2]["extensions"]["EXT_meshopt_compression"]["byteStride"] = 6;
  const std::string odd = dir.file("stride.glb");
  write_glb_parts(odd, stride);
  expect_gltf_error(odd, "bufferViews[2].extensions.EXT_meshopt_compression ATTRIBUTES has byteStride 6 (4 to 256, a multiple of 4)",
                    [&] { load_gltf(odd); });

  // A 61-byte stream that claims 64 MiB (with a view of that size, behind a fallback buffer that
  // claims more) is refused before 64 MiB are allocated. (A .gltf: a .glb's fallback buffer is no
  // longer than its binary chunk.)
  GlbParts huge = split_glb(asset(kMeshoptBox));
  huge.doc["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["count"] = 1 << 24;
  huge.doc["bufferViews"][1]["byteLength"] = 1 << 26;
  huge.doc["buffers"][1]["byteLength"] = 1 << 27;
  huge.doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(huge.bin);
  const std::string claims = dir.file("claims.gltf");
  write_text(claims, huge.doc.dump());
  expect_gltf_error(claims, "bufferViews[1].extensions.EXT_meshopt_compression claims 67108864 bytes from 61, more than meshoptimizer's encoding holds",
                    [&] { load_gltf(claims); });

  GlbParts outside = split_glb(asset(kMeshoptBox));
  outside.doc["bufferViews"][4]["extensions"]["EXT_meshopt_compression"]["byteOffset"] = 1u << 30;
  const std::string far = dir.file("outside.glb");
  write_glb_parts(far, outside);
  expect_gltf_error(far, "bufferViews[4].extensions.EXT_meshopt_compression reads bytes 1073741824 + 29 of buffer 0", [&] { load_gltf(far); });
}

// gltfpack's .gltf output: the fallback buffer has no URI.
TEST(GltfCompression, AGltfWhoseFallbackBufferHasNoUriLoads) {
  TempDir dir;
  GlbParts parts = split_glb(asset(kMeshoptBox));
  ASSERT_FALSE(parts.doc["buffers"][1].contains("uri"));
  parts.doc["buffers"][0]["uri"] = "box.bin";
  write_bytes(dir.file("box.bin"), parts.bin);
  const std::string path = dir.file("box.gltf");
  write_text(path, parts.doc.dump());
  const Scene a = load_gltf(path, no_defaults()), b = load_gltf(asset(kMeshoptBox), no_defaults());
  ASSERT_EQ(a.meshes.size(), 1u);
  EXPECT_EQ(a.meshes[0].positions, b.meshes[0].positions);
  EXPECT_EQ(a.meshes[0].normals, b.meshes[0].normals);
}

TEST(GltfCompression, QuantizedAttributesNeedTheExtension) {
  TempDir dir;
  GlbParts parts = split_glb(asset(kMeshoptBox));
  parts.doc["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_texture_transform"};
  parts.doc["extensionsRequired"] = {"EXT_meshopt_compression"};
  const std::string path = dir.file("unquantized.glb");
  write_glb_parts(path, parts);
  expect_gltf_error(path, "mesh 0 primitive 0 POSITION (accessor 1) may not be UNSIGNED_SHORT (without KHR_mesh_quantization)", [&] { load_gltf(path); });
}

TEST(GltfCompression, ABrokenDracoStreamIsNamed) {
  TempDir dir;
  GlbParts parts = split_glb(asset(kDracoBox));
  const json& view = parts.doc["bufferViews"][parts.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"].get<int>()];
  const size_t at = view.value("byteOffset", 0), length = view["byteLength"].get<size_t>();
  for (size_t i = at + 8; i < at + length; ++i) parts.bin[i] = uint8_t(i * 37);
  const std::string garbage = dir.file("garbage.glb");
  write_glb_parts(garbage, parts);
  expect_gltf_error(garbage, "meshes[0].primitives[0]: the Draco stream does not decode", [&] { load_gltf(garbage); });

  GlbParts count = split_glb(asset(kDracoBox));
  const int position = count.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<int>();
  count.doc["accessors"][position]["count"] = 25;
  const std::string miscounted = dir.file("count.glb");
  write_glb_parts(miscounted, count);
  expect_gltf_error(miscounted, "meshes[0].primitives[0] Draco attribute POSITION has 24 values; its accessor has 25",
                    [&] { load_gltf(miscounted); });

  GlbParts unknown = split_glb(asset(kDracoBox));
  unknown.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 9;
  const std::string missing = dir.file("attribute.glb");
  write_glb_parts(missing, unknown);
  expect_gltf_error(missing, "meshes[0].primitives[0] Draco attribute NORMAL names no attribute of the Draco stream",
                    [&] { load_gltf(missing); });
}

/// LEB128, as Draco writes its counts.
std::vector<uint8_t> draco_varint(uint64_t n) {
  std::vector<uint8_t> out;
  do {
    out.push_back(uint8_t((n & 0x7f) | (n >= 0x80 ? 0x80 : 0)));
    n >>= 7;
  } while (n);
  return out;
}

// A Draco stream of 80 bytes whose sequential connectivity claims two billion triangles: refused
// as a stream that does not decode, not read as a request for 24 GB.
TEST(GltfCompression, ADracoStreamClaimingHugeCountsIsRefused) {
  TempDir dir;
  std::vector<uint8_t> stream = {'D', 'R', 'A', 'C', 'O', 2, 2, 1, 0, 0, 0};  // version 2.2, mesh, sequential, no flags
  for (uint64_t count : {uint64_t(2'000'000'000), uint64_t(1'000'000)}) {
    const std::vector<uint8_t> v = draco_varint(count);
    stream.insert(stream.end(), v.begin(), v.end());
  }
  stream.push_back(1);  // uncompressed indices
  stream.resize(stream.size() + 64, 0);
  GltfBuilder b;
  b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  b.buffer.bytes = stream;
  b.doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", stream.size()}}};
  b.doc["accessors"] = {{{"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}, {{"componentType", 5125}, {"count", 3}, {"type", "SCALAR"}}};
  b.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1},
                                        {"extensions", {{"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}}}}}}}};
  b.add_node({{"mesh", 0}});
  const std::string path = b.write(dir);
  expect_gltf_error(path, "meshes[0].primitives[0]: the Draco stream does not decode", [&] { load_gltf(path); });
}

}  // namespace
}  // namespace luxel::scenes::test
