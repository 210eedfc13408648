#pragma once
// tinygltf 2.7 as luxel builds it (one place for the macros every includer must agree on):
// no stb_image (images decode through image_io.hpp, from a callback), no stb_image_write (export
// embeds PNG bytes it encodes itself), and no external images (luxel opens image files itself,
// after confining their URIs to the glTF's folder).
#pragma GCC system_header

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
