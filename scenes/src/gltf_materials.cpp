#include "gltf_materials.hpp"

#include "gltf_values.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace luxel::scenes::gltf {

namespace {

using tinygltf::Value;

// --- The Source parameters in extras.luxel (gltf.hpp lists them) ---------------------------------

struct FloatKey { const char* key; float Material::*member; };
struct Vec3Key { const char* key; glm::vec3 Material::*member; };
struct BoolKey { const char* key; bool Material::*member; };
struct TextureKey { const char* key; TextureRef Material::*member; ColorSpace color_space; };

constexpr FloatKey kFloats[] = {
    {"detailscale", &Material::detail_scale},         {"detailblendfactor", &Material::detail_blend},
    {"envmapcontrast", &Material::envmap_contrast},   {"envmapsaturation", &Material::envmap_saturation},
    {"envmapfresnel", &Material::envmap_fresnel},
    {"fresnelreflection", &Material::fresnel_reflection}, {"phongexponent", &Material::phong_exponent},
    {"phongexponentfactor", &Material::phong_exponent_factor},
    {"phongboost", &Material::phong_boost},           {"rimlightexponent", &Material::rim_exponent},
    {"rimlightboost", &Material::rim_boost},          {"heroboost", &Material::hero_boost},
    {"alphatestreference", &Material::alpha_cutoff},  {"reflectamount", &Material::reflect_amount},
    {"refractamount", &Material::refract_amount},     {"fogstart", &Material::water_fog_start},
    {"fogend", &Material::water_fog_end},
};
constexpr Vec3Key kVec3s[] = {
    {"envmaptint", &Material::envmap_tint},     {"phongfresnelranges", &Material::phong_fresnel_ranges},
    {"phongtint", &Material::phong_tint},       {"selfillumtint", &Material::self_illum_tint},
    {"emissive", &Material::emissive},          {"reflecttint", &Material::reflect_tint},
    {"refracttint", &Material::refract_tint},   {"fogcolor", &Material::water_fog_color},
};
constexpr BoolKey kBools[] = {
    {"phong", &Material::phong},         {"basemapalphaphongmask", &Material::base_map_alpha_phong_mask},
    {"rimlight", &Material::rim},        {"rimmask", &Material::rim_mask},
    {"halflambert", &Material::half_lambert}, {"selfillum", &Material::self_illum},
    {"translucent", &Material::translucent},  {"nocull", &Material::double_sided},
    {"blurrefract", &Material::water_blur_refract}, {"phongalbedotint", &Material::phong_albedo_tint},
    {"invertphongmask", &Material::invert_phong_mask},
};
constexpr TextureKey kTextures[] = {
    {"basetexture", &Material::base, ColorSpace::srgb},
    {"bumpmap", &Material::bump, ColorSpace::linear},
    {"detail", &Material::detail, ColorSpace::srgb},
    {"envmapmasktexture", &Material::envmap_mask_texture, ColorSpace::linear},
    {"phongexponenttexture", &Material::phong_exponent_texture, ColorSpace::linear},
    {"normalmap", &Material::water_normal, ColorSpace::linear},
};

constexpr std::array<std::pair<ShaderFamily, const char*>, 5> kShaders = {{
    {ShaderFamily::lightmapped_generic, "LightmappedGeneric"},
    {ShaderFamily::vertexlit_generic, "VertexLitGeneric"},
    {ShaderFamily::unlit_generic, "UnlitGeneric"},
    {ShaderFamily::water, "Water"},
    {ShaderFamily::sky, "Sky"},
}};
constexpr std::array<std::pair<EnvmapMask, const char*>, 4> kMasks = {{
    {EnvmapMask::none, ""}, {EnvmapMask::texture, "texture"},
    {EnvmapMask::base_alpha, "basealpha"}, {EnvmapMask::normal_alpha, "normalalpha"},
}};

void read_transform(const Value& t, TextureRef& ref) {
  if (!t.IsObject()) return;
  read(t.Get("offset"), ref.offset);
  read(t.Get("scale"), ref.scale);
  read(t.Get("rotation"), ref.rotation);
  read(t.Get("texCoord"), ref.uv_set);
}

bool has_transform(const TextureRef& r) { return r.offset != glm::vec2(0.0f) || r.scale != glm::vec2(1.0f) || r.rotation != 0.0f; }

Value transform_value(const TextureRef& r) {
  Value::Object t;
  t["offset"] = floats(r.offset);
  t["scale"] = floats(r.scale);
  t["rotation"] = Value(double(r.rotation));
  return Value(std::move(t));
}

}  // namespace

void apply_texture_transform(const tinygltf::ExtensionMap& extensions, TextureRef& ref) {
  if (auto it = extensions.find("KHR_texture_transform"); it != extensions.end()) read_transform(it->second, ref);
}

Material material_from_gltf(const tinygltf::Material& g, size_t index, const ResolveTexture& resolve,
                            const std::function<void(const std::string&)>& fail) {
  Material m;
  m.name = g.name.empty() ? "material " + std::to_string(index) : g.name;
  const std::string where = "material " + std::to_string(index) + (g.name.empty() ? "" : " '" + g.name + "'");
  auto ref = [&](int texture, int tex_coord, const tinygltf::ExtensionMap& ext, ColorSpace cs, const char* slot) {
    TextureRef r;
    if (texture < 0) return r;
    r.texture = resolve(texture, cs, where + " " + slot);
    r.uv_set = tex_coord;
    apply_texture_transform(ext, r);
    if (r.uv_set != 0 && r.uv_set != 1)
      fail(where + " " + slot + " reads TEXCOORD_" + std::to_string(r.uv_set) + "; luxel reads TEXCOORD_0 and _1");
    return r;
  };
  const auto& pbr = g.pbrMetallicRoughness;
  m.base = ref(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions,
               ColorSpace::srgb, "base color texture");
  if (pbr.baseColorFactor.size() == 4)
    m.color = glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]), float(pbr.baseColorFactor[2]),
                        float(pbr.baseColorFactor[3]));
  m.bump = ref(g.normalTexture.index, g.normalTexture.texCoord, g.normalTexture.extensions, ColorSpace::linear,
               "normal texture");
  const float r = std::clamp(float(pbr.roughnessFactor), 0.0f, 1.0f), metal = std::clamp(float(pbr.metallicFactor), 0.0f, 1.0f);
  m.phong = r < 0.9f;
  m.phong_exponent = std::clamp(2.0f / std::max(r * r * r * r, 1e-6f) - 2.0f, 1.0f, 150.0f);
  if (metal > 0.0f && r < 0.5f) {
    m.envmap = EnvmapSource::nearest_sample;
    m.envmap_tint = (glm::vec3(0.04f) + (glm::vec3(m.color) - glm::vec3(0.04f)) * metal) * (1.0f - r);
  }
  float strength = 1.0f;
  if (auto it = g.extensions.find("KHR_materials_emissive_strength"); it != g.extensions.end())
    read(it->second.Get("emissiveStrength"), strength);
  if (g.emissiveFactor.size() == 3)
    m.emissive = glm::vec3(float(g.emissiveFactor[0]), float(g.emissiveFactor[1]), float(g.emissiveFactor[2])) * strength;
  if (g.alphaMode == "MASK") m.alpha = AlphaMode::alpha_test;
  else if (g.alphaMode == "BLEND") m.alpha = AlphaMode::blend, m.translucent = true;
  m.alpha_cutoff = float(g.alphaCutoff);
  m.double_sided = g.doubleSided;
  if (g.extensions.count("KHR_materials_unlit")) m.family = ShaderFamily::unlit_generic;

  // Source parameters from extras.luxel override the mapping.
  const Value& x = g.extras.Get("luxel");
  if (!x.IsObject()) return m;
  if (const Value& s = x.Get("shader"); s.IsString()) {
    auto it = std::find_if(kShaders.begin(), kShaders.end(), [&](const auto& p) { return s.Get<std::string>() == p.second; });
    if (it == kShaders.end()) fail(where + " extras ask for shader '" + s.Get<std::string>() + "', which luxel does not have");
    m.family = it->first;
  }
  for (const FloatKey& k : kFloats) read(x.Get(k.key), m.*k.member);
  for (const Vec3Key& k : kVec3s) read(x.Get(k.key), m.*k.member);
  for (const BoolKey& k : kBools) read(x.Get(k.key), m.*k.member);
  for (const TextureKey& k : kTextures) {
    const Value& t = x.Get(k.key);
    if (!t.IsObject() || !t.Get("index").IsNumber()) continue;
    const std::optional<int> texture = integer(t.Get("index"));
    if (!texture) {
      fail(where + " extras " + k.key + " refers to texture " + number_text(t.Get("index")) + ", which is not an index");
      continue;  // (fail throws)
    }
    TextureRef& r = m.*k.member;
    r = TextureRef{};
    r.texture = resolve(*texture, k.color_space, where + " extras " + k.key);
    read_transform(t, r);  // texCoord, offset, scale, rotation
  }
  glm::vec3 rgb(m.color);
  read(x.Get("color"), rgb);
  m.color = glm::vec4(rgb, m.color.a);
  read(x.Get("alpha"), m.color.a);
  read(x.Get("scroll1"), m.water_scroll);
  if (const Value& e = x.Get("envmap"); e.IsString())
    m.envmap = e.Get<std::string>() == "env_cubemap" ? EnvmapSource::nearest_sample : EnvmapSource::none;
  if (const Value& e = x.Get("envmapmask"); e.IsString()) {
    auto it = std::find_if(kMasks.begin(), kMasks.end(), [&](const auto& p) { return e.Get<std::string>() == p.second; });
    if (it == kMasks.end()) fail(where + " extras envmapmask '" + e.Get<std::string>() + "' is not texture, basealpha or normalalpha");
    m.envmap_mask = it->first;
  }
  return m;
}

tinygltf::Material material_to_gltf(const Material& m, const std::function<int(int)>& to_gltf,
                                    std::set<std::string>& extensions_used) {
  tinygltf::Material g;
  g.name = m.name;
  auto info = [&](const TextureRef& r, auto& out) {
    const int index = r.bound() ? to_gltf(r.texture) : -1;
    if (index < 0) return;
    out.index = index;
    out.texCoord = r.uv_set;
    if (has_transform(r)) {
      out.extensions["KHR_texture_transform"] = transform_value(r);
      extensions_used.insert("KHR_texture_transform");
    }
  };
  info(m.base, g.pbrMetallicRoughness.baseColorTexture);
  info(m.bump, g.normalTexture);
  g.pbrMetallicRoughness.baseColorFactor = {m.color.r, m.color.g, m.color.b, m.color.a};
  // The inverse of the import mapping's exponent, so a viewer shows a similar highlight.
  const double exponent = m.phong_exponent > 0.0f ? std::max(double(m.phong_exponent), 1.0) : 150.0;  // unset: 150
  g.pbrMetallicRoughness.roughnessFactor = m.phong ? std::clamp(std::pow(2.0 / (exponent + 2.0), 0.25), 0.0, 1.0) : 1.0;
  g.pbrMetallicRoughness.metallicFactor = 0.0;
  const float peak = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
  if (peak > 0.0f) {
    const float strength = std::max(peak, 1.0f);
    g.emissiveFactor = {m.emissive.r / strength, m.emissive.g / strength, m.emissive.b / strength};
    if (strength > 1.0f) {
      Value::Object s;
      s["emissiveStrength"] = Value(double(strength));
      g.extensions["KHR_materials_emissive_strength"] = Value(std::move(s));
      extensions_used.insert("KHR_materials_emissive_strength");
    }
  }
  g.alphaMode = m.alpha == AlphaMode::alpha_test ? "MASK" : m.alpha == AlphaMode::blend ? "BLEND" : "OPAQUE";
  g.alphaCutoff = m.alpha_cutoff;
  g.doubleSided = m.double_sided;
  if (m.family == ShaderFamily::unlit_generic) {
    g.extensions["KHR_materials_unlit"] = Value(Value::Object{});
    extensions_used.insert("KHR_materials_unlit");
  }

  Value::Object x;
  for (const auto& [family, name] : kShaders)
    if (family == m.family) x["shader"] = Value(std::string(name));
  for (const FloatKey& k : kFloats) x[k.key] = Value(double(m.*k.member));
  for (const Vec3Key& k : kVec3s) x[k.key] = floats(m.*k.member);
  for (const BoolKey& k : kBools) x[k.key] = Value(m.*k.member);
  for (const TextureKey& k : kTextures) {
    const TextureRef& r = m.*k.member;
    const int index = r.bound() ? to_gltf(r.texture) : -1;
    if (index < 0) continue;
    Value::Object t;
    t["index"] = Value(index);
    t["texCoord"] = Value(r.uv_set);
    t["offset"] = floats(r.offset);
    t["scale"] = floats(r.scale);
    t["rotation"] = Value(double(r.rotation));
    x[k.key] = Value(std::move(t));
  }
  x["color"] = floats(glm::vec3(m.color));
  x["alpha"] = Value(double(m.color.a));
  x["scroll1"] = floats(m.water_scroll);
  // A texture env map cannot be exported (cube): it asks for the nearest sample instead.
  x["envmap"] = Value(std::string(m.envmap == EnvmapSource::none ? "" : "env_cubemap"));
  for (const auto& [mask, name] : kMasks)
    if (mask == m.envmap_mask) x["envmapmask"] = Value(std::string(name));
  Value::Object extras;
  extras["luxel"] = Value(std::move(x));
  g.extras = Value(std::move(extras));
  return g;
}

}  // namespace luxel::scenes::gltf
