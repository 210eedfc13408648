// load_scene: the one resolver of scene arguments (load.hpp).

#include "gltf_support.hpp"

#include "luxel/scenes/load.hpp"

namespace luxel::scenes::test {
namespace {

template <class Error, class Fn>
std::string message_of(Fn fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error of the expected type)";
}

TEST(LoadScene, ArgumentsThatNameNoScene) {
  EXPECT_EQ(message_of<SceneArgumentError>([] { load_scene("builtin:nope"); }),
            "builtin:nope: unknown built-in scene 'nope' (known: courtyard, demo, fill, tris)");
  EXPECT_EQ(message_of<SceneArgumentError>([] { load_scene("scene.obj"); }),
            "scene.obj: not a scene: name a .gltf or .glb file, or builtin:NAME");
}

TEST(LoadScene, BuiltinScenesByName) {
  const Scene demo = load_scene("builtin:demo");
  EXPECT_FALSE(demo.meshes.empty());
  EXPECT_EQ(demo.meshes.size(), make_builtin_scene("demo").meshes.size());
  // The built-in options reach the scene: tris is laid out in pixels of the image it is built for.
  const Bounds small = bounds_of(load_scene("builtin:tris", {}, {64, 48}));
  EXPECT_LE(small.max.x, 64.0f + 4.0f);
  EXPECT_GT(bounds_of(load_scene("builtin:tris")).max.x, 1000.0f);
}

TEST(LoadScene, GltfFilesByExtensionInAnyCase) {
  EXPECT_TRUE(has_extension("a/B.GLB", ".glb"));
  EXPECT_TRUE(has_extension("x.Gltf", ".gltf"));
  EXPECT_FALSE(has_extension("x.gltf.bak", ".gltf"));
  EXPECT_FALSE(has_extension("glb", ".glb"));
  const Scene s = load_scene(asset("box-textured/glTF-Binary/BoxTextured.glb"));
  EXPECT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(message_of<GltfError>([] { load_scene("/nonexistent/X.GLB"); }),
            "/nonexistent/X.GLB: cannot open it: No such file or directory");
}

}  // namespace
}  // namespace luxel::scenes::test
