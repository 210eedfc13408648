#pragma once
// glTF materials <-> Source materials: the table gltf.hpp documents, written once for both
// directions (the extras keys and the Material members they set).

#include "luxel/scenes/scene.hpp"
#include "tinygltf.hpp"

#include <functional>
#include <set>
#include <string>

namespace luxel::scenes::gltf {

/// Maps a glTF texture index, read with the given color space, to a Scene::textures index;
/// `where` names the reference in messages. Throws on a bad index or an unreadable image.
using ResolveTexture = std::function<int(int gltf_texture, ColorSpace, const std::string& where)>;

/// The Source material for glTF material `index`: the PBR mapping, then extras.luxel.
/// `fail` throws with the message given.
Material material_from_gltf(const tinygltf::Material& m, size_t index, const ResolveTexture& resolve,
                            const std::function<void(const std::string&)>& fail);

/// The glTF material for a Source one: PBR fields as close as the mapping allows, every Source
/// parameter in extras.luxel. `to_gltf` maps a Scene::textures index to a glTF texture index (-1:
/// not exported). Extensions it uses are added to `extensions_used`.
tinygltf::Material material_to_gltf(const Material& m, const std::function<int(int)>& to_gltf,
                                    std::set<std::string>& extensions_used);

/// KHR_texture_transform (and texCoord) of a textureInfo's extensions applied to `ref`.
void apply_texture_transform(const tinygltf::ExtensionMap& extensions, TextureRef& ref);

}  // namespace luxel::scenes::gltf
