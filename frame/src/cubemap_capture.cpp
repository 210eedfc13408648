// Cube-map faces through the frame: face cameras, the exposure bracket, 8-bit and float captures,
// the merged cube (cubemaps.hpp).
#include "luxel/frame/cubemaps.hpp"

#include "luxel/frame/exposure_merge.hpp"
#include "luxel/frame/renderer.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace luxel::frame {

namespace {

using rasterizer::CubeFace;

/// The frame's settings for one face.
FrameSettings face_settings(glm::vec3 position, CubeFace face, int size, float exposure, shading::ShaderModel model) {
  FrameSettings s;
  s.width = s.height = size;
  s.samples = 1;
  s.model = model;
  s.exposure = exposure;
  s.view = cube_face_camera(position, face);
  s.cubemap_capture = true;
  return s;
}

/// Whether the right-handed face camera sees the cube's layout mirrored left to right.
bool mirrored(CubeFace face) {
  const glm::vec3 forward = rasterizer::cube_direction(face, 0.5f, 0.5f);
  const glm::vec3 up = rasterizer::cube_direction(face, 0.5f, 0.0f) - forward;
  const glm::vec3 right = rasterizer::cube_direction(face, 1.0f, 0.5f) - forward;
  return glm::dot(glm::cross(forward, up), right) < 0.0f;
}

template <class T>
void mirror_rows(std::vector<T>& texels, int width, int height, int per_texel) {
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width / 2; ++x)
      for (int c = 0; c < per_texel; ++c)
        std::swap(texels[(size_t(y) * width + x) * per_texel + c], texels[(size_t(y) * width + (width - 1 - x)) * per_texel + c]);
}

float max_channel(const scenes::PixelImage& image, size_t i) {
  if (image.is_hdr()) return std::max({image.rgba32f[4 * i], image.rgba32f[4 * i + 1], image.rgba32f[4 * i + 2]});
  return std::max({image.rgba8[4 * i], image.rgba8[4 * i + 1], image.rgba8[4 * i + 2]}) / 255.0f;
}

/// The largest value among the images' texels and the smallest positive one (0: none).
std::pair<float, float> texel_range(const scenes::Texture& t, std::vector<float>* values = nullptr) {
  float hi = 0.0f, lo = 0.0f;
  for (const scenes::PixelImage& image : t.faces)
    for (size_t i = 0; i < size_t(image.width) * size_t(image.height); ++i) {
      const float v = max_channel(image, i);
      if (!std::isfinite(v)) continue;
      hi = std::max(hi, v);
      if (v > 0.0f) lo = lo > 0.0f ? std::min(lo, v) : v;
      if (values && v > 0.0f) values->push_back(v);
    }
  return {hi, lo};
}

}  // namespace

scenes::Camera cube_face_camera(glm::vec3 position, CubeFace face) {
  scenes::Camera c;
  c.name = "cube face " + std::to_string(int(face));
  c.position = position;
  c.target = position + rasterizer::cube_direction(face, 0.5f, 0.5f);
  c.up = rasterizer::cube_direction(face, 0.5f, 0.0f) - rasterizer::cube_direction(face, 0.5f, 0.5f);
  c.vertical_fov = float(std::numbers::pi / 2);
  c.aspect = 1.0f;
  c.near_plane = 1.0f;
  return c;
}

std::vector<float> exposure_bracket(const scenes::Scene& scene, float stops_apart) {
  if (!(std::isfinite(stops_apart) && stops_apart > 0.0f))
    throw std::invalid_argument("cube maps: exposures " + std::to_string(stops_apart) + " stops apart is not a positive number");
  float brightest = 0.0f, dimmest = 0.0f;
  if (scene.sky_texture >= 0) {
    const auto [hi, lo] = texel_range(scene.textures[size_t(scene.sky_texture)]);
    brightest = std::max(brightest, hi), dimmest = lo;
  }
  for (const scenes::Material& m : scene.materials) brightest = std::max({brightest, m.emissive.r, m.emissive.g, m.emissive.b});
  if (scene.lightmaps && scene.lightmaps->flat >= 0) {
    std::vector<float> values;
    const auto [hi, lo] = texel_range(scene.textures[size_t(scene.lightmaps->flat)], &values);
    brightest = std::max(brightest, hi);
    if (!values.empty()) {
      std::nth_element(values.begin(), values.begin() + values.size() / 100, values.end());
      const float dim = kDarkAlbedo * values[values.size() / 100];
      dimmest = dimmest > 0.0f ? std::min(dimmest, dim) : dim;
    }
  }
  if (brightest <= 0.0f) brightest = 1.0f;
  if (dimmest <= 0.0f || dimmest > brightest) dimmest = brightest;
  const float low = std::floor(std::log2(0.9f / brightest));
  const float high = std::max(low, std::ceil(std::log2(0.25f / dimmest)));
  // A range beyond 32 stops is a scene error (a stray huge or tiny texel); the bracket stops there.
  const int count = 1 + std::min(int(std::ceil((high - low) / stops_apart)), int(32.0f / stops_apart));
  std::vector<float> exposures;
  for (int k = 0; k < count; ++k) exposures.push_back(std::exp2(low + k * stops_apart));
  return exposures;
}

rasterizer::Image capture_face(const scenes::Scene& scene, glm::vec3 position, CubeFace face, int size, float exposure,
                               shading::ShaderModel model, rasterizer::Context& ctx,
                               std::shared_ptr<const SceneTextures> textures) {
  Renderer renderer(scene, face_settings(position, face, size, exposure, model), std::move(textures));
  renderer.render(ctx);
  rasterizer::Image image = renderer.image();
  if (mirrored(face)) mirror_rows(image.rgba, image.width, image.height, 4);
  return image;
}

std::vector<glm::vec4> capture_face_float(const scenes::Scene& scene, glm::vec3 position, CubeFace face, int size,
                                          shading::ShaderModel model, rasterizer::Context& ctx,
                                          std::shared_ptr<const SceneTextures> textures) {
  Renderer renderer(scene, face_settings(position, face, size, 1.0f, model), std::move(textures));
  std::vector<glm::vec4> texels = renderer.render_float(ctx);
  if (mirrored(face)) mirror_rows(texels, size, size, 1);
  return texels;
}

scenes::Texture bake_cubemap(const scenes::Scene& scene, glm::vec3 position, int size, std::span<const float> exposures,
                             shading::ShaderModel model, rasterizer::Context& ctx, std::string name,
                             std::shared_ptr<const SceneTextures> textures) {
  if (!textures) {
    scenes::validate(scene);  // before its textures are prepared
    textures = std::make_shared<const SceneTextures>(scene);
  }
  std::vector<scenes::PixelImage> faces;
  for (int f = 0; f < 6; ++f) {
    std::vector<rasterizer::Image> images;
    for (float e : exposures) images.push_back(capture_face(scene, position, CubeFace(f), size, e, model, ctx, textures));
    const std::vector<glm::vec4> merged = merge_exposures(images, exposures);
    scenes::PixelImage face;
    face.width = face.height = size;
    face.rgba32f.reserve(merged.size() * 4);
    for (const glm::vec4& t : merged)
      for (int c = 0; c < 4; ++c)  // as RGBA16F holds it (and EXR keeps it): half floats
        face.rgba32f.push_back(glm::unpackHalf1x16(glm::packHalf1x16(std::min(t[c], 65504.0f))));
    faces.push_back(std::move(face));
  }
  return cubemap_texture(std::move(name), std::move(faces));
}

scenes::Texture cubemap_texture(std::string name, std::vector<scenes::PixelImage> faces) {
  scenes::Texture t;
  t.name = std::move(name);
  t.shape = scenes::TextureShape::cube;
  t.color_space = scenes::ColorSpace::linear;
  t.faces = std::move(faces);
  t.wrap_u = t.wrap_v = scenes::Wrap::clamp;
  t.mag = t.min = scenes::Filter::linear;
  t.mipmaps = true;
  return t;
}

std::vector<scenes::Texture> bake_cubemaps(const scenes::Scene& scene, const CubemapSettings& settings,
                                           rasterizer::Context& ctx, const CubemapProgressFn& progress) {
  if (settings.face_size < 0 || settings.face_size > rasterizer::kMaxTextureSize)
    throw std::invalid_argument("cube maps: face size " + std::to_string(settings.face_size) + " is outside 0.." +
                                std::to_string(rasterizer::kMaxTextureSize));
  const std::vector<float> exposures = exposure_bracket(scene, settings.stops_apart);
  scenes::validate(scene);  // before its textures are prepared
  const auto textures = std::make_shared<const SceneTextures>(scene);
  std::vector<scenes::Texture> cubes;
  const int total = int(scene.cubemap_samples.size());
  for (int i = 0; i < total; ++i) {
    const scenes::CubemapSample& s = scene.cubemap_samples[size_t(i)];
    const int size = settings.face_size > 0 ? settings.face_size : s.size;
    if (size < 1 || size > rasterizer::kMaxTextureSize)
      throw std::invalid_argument(scene.name + ": cube-map sample " + std::to_string(i) + " has size " + std::to_string(size) +
                                  ", outside 1.." + std::to_string(rasterizer::kMaxTextureSize));
    cubes.push_back(
        bake_cubemap(scene, s.position, size, exposures, settings.model, ctx, "cubemap " + std::to_string(i), textures));
    if (progress) progress(i + 1, total);
  }
  return cubes;
}

void attach_cubemaps(scenes::Scene& scene, std::vector<scenes::Texture> cubes) {
  if (cubes.size() != scene.cubemap_samples.size())
    throw std::invalid_argument(scene.name + ": " + std::to_string(cubes.size()) + " cube maps for " +
                                std::to_string(scene.cubemap_samples.size()) + " cube-map samples");
  for (size_t i = 0; i < cubes.size(); ++i) {
    scene.textures.push_back(cubemap_texture(std::move(cubes[i].name), std::move(cubes[i].faces)));
    scene.cubemap_samples[i].texture = int(scene.textures.size()) - 1;
  }
}

}  // namespace luxel::frame
