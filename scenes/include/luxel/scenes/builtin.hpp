#pragma once
// Built-in scenes: scenes made in code, needing no files, as plain data like any other Scene.
//
//   demo       a checkered ground running to the horizon and a ring of brick cubes (perspective)
//   fill       W1 of the llvmpipe peer (bench/README.md): 8 full-screen layers
//   tris       W2 of the peer: one million small flat-colored triangles, laid out in pixels
//   courtyard  a walled courtyard that uses every technique of the Source pipeline at once
//
// Every built-in scene passes validate() and is deterministic: the same name and options give the
// same bytes in every array. Procedural textures are built in code.

#include "luxel/scenes/scene.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace luxel::scenes {

/// What a built-in scene may depend on. Only `tris` reads it: the peer defines W2 in pixels of
/// the frame it is drawn into (its triangles are 2 to 4 pixels^2 at any size), so it is built for
/// one image size; every other scene ignores it.
struct BuiltinOptions {
  int width = 1280, height = 720;
};

/// The names make_builtin_scene accepts, in display order.
std::vector<std::string> builtin_scene_names();

/// Builds the built-in scene `name` (without the "builtin:" prefix). Throws std::invalid_argument
/// "unknown built-in scene 'x' (known: ...)" for any other name, and for options out of range.
Scene make_builtin_scene(std::string_view name, const BuiltinOptions& options = {});

}  // namespace luxel::scenes
