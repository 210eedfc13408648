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
  EXPECT_EQ(message_of<SceneArgumentError>([] { load_scene("builtin:courtyard"); }),
            "builtin:courtyard: built-in scenes are not on this branch");
  EXPECT_EQ(message_of<SceneArgumentError>([] { load_scene("scene.obj"); }),
            "scene.obj: not a scene: name a .gltf or .glb file, or builtin:NAME");
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
