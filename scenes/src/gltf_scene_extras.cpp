#include "gltf_scene_extras.hpp"

#include "gltf_values.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace luxel::scenes::gltf {

namespace {

using tinygltf::Value;

constexpr std::array<std::pair<FogMode, const char*>, 3> kFogModes = {{{FogMode::none, "none"}, {FogMode::range, "range"}, {FogMode::height, "height"}}};
constexpr std::array<std::pair<ColorCorrectionInput::Kind, const char*>, 2> kInputKinds = {
    {{ColorCorrectionInput::Kind::enable, "enable"}, {ColorCorrectionInput::Kind::disable, "disable"}}};

Value camera_value(const Camera& c) {
  Value::Object o;
  o["position"] = floats(c.position);
  o["target"] = floats(c.target);
  o["up"] = floats(c.up);
  o["fov"] = Value(double(c.vertical_fov));
  o["near"] = Value(double(c.near_plane));
  o["far"] = Value(double(c.far_plane));
  return Value(std::move(o));
}

void read_camera(const Value& v, Camera& c) {
  read(v.Get("position"), c.position);
  read(v.Get("target"), c.target);
  read(v.Get("up"), c.up);
  read(v.Get("fov"), c.vertical_fov);
  read(v.Get("near"), c.near_plane);
  read(v.Get("far"), c.far_plane);
}

Value exposure_value(const Exposure& e) {
  Value::Object o;
  o["minscale"] = Value(double(e.min_scale));
  o["maxscale"] = Value(double(e.max_scale));
  o["rate"] = Value(double(e.rate));
  o["percenttarget"] = Value(double(e.percent_target));
  o["percentbright"] = Value(double(e.percent_bright));
  o["bloomscale"] = Value(double(e.bloom_scale));
  return Value(std::move(o));
}

void read_exposure(const Value& v, Exposure& e) {
  if (!v.IsObject()) return;
  read(v.Get("minscale"), e.min_scale);
  read(v.Get("maxscale"), e.max_scale);
  read(v.Get("rate"), e.rate);
  read(v.Get("percenttarget"), e.percent_target);
  read(v.Get("percentbright"), e.percent_bright);
  read(v.Get("bloomscale"), e.bloom_scale);
}

Value color_correction_value(const ColorCorrection& c) {
  Value::Object o;
  o["lut"] = Value(c.lut);
  o["position"] = floats(c.position);
  o["minfalloff"] = Value(double(c.min_falloff));
  o["maxfalloff"] = Value(double(c.max_falloff));
  o["maxweight"] = Value(double(c.max_weight));
  o["fadein"] = Value(double(c.fade_in));
  o["fadeout"] = Value(double(c.fade_out));
  o["startdisabled"] = Value(c.start_disabled);
  Value::Array inputs;
  for (const ColorCorrectionInput& in : c.inputs) {
    Value::Object i;
    i["time"] = Value(double(in.time));
    for (const auto& [kind, name] : kInputKinds)
      if (kind == in.kind) i["input"] = Value(std::string(name));
    inputs.emplace_back(std::move(i));
  }
  o["inputs"] = Value(std::move(inputs));
  return Value(std::move(o));
}

/// Node `index` as the extras hold it; keys it lacks keep their defaults (files written before
/// fades existed).
ColorCorrection read_color_correction(const Value& o, size_t index, const std::function<void(const std::string&)>& fail) {
  ColorCorrection c;
  if (o.Get("lut").IsString()) c.lut = o.Get("lut").Get<std::string>();
  read(o.Get("position"), c.position);
  read(o.Get("minfalloff"), c.min_falloff);
  read(o.Get("maxfalloff"), c.max_falloff);
  read(o.Get("maxweight"), c.max_weight);
  read(o.Get("fadein"), c.fade_in);
  read(o.Get("fadeout"), c.fade_out);
  read(o.Get("startdisabled"), c.start_disabled);
  const Value& inputs = o.Get("inputs");
  for (size_t k = 0; inputs.IsArray() && k < inputs.ArrayLen(); ++k) {
    const Value& i = inputs.Get(int(k));
    ColorCorrectionInput in;
    read(i.Get("time"), in.time);
    const std::string name = i.Get("input").IsString() ? i.Get("input").Get<std::string>() : "";
    const auto known = std::find_if(kInputKinds.begin(), kInputKinds.end(), [&](const auto& k) { return name == k.second; });
    if (known == kInputKinds.end())
      fail("color correction " + std::to_string(index) + " input " + std::to_string(k) + " is '" + name +
           "', not enable or disable");
    in.kind = known->first;
    c.inputs.push_back(in);
  }
  return c;
}

}  // namespace

Value scene_extras(const Scene& s) {
  Value::Object x;
  x["background"] = floats(s.background);
  Value::Object fog;
  for (const auto& [mode, name] : kFogModes)
    if (mode == s.fog.mode) fog["mode"] = Value(std::string(name));
  fog["color"] = floats(s.fog.color);
  fog["start"] = Value(double(s.fog.start));
  fog["end"] = Value(double(s.fog.end));
  fog["maxdensity"] = Value(double(s.fog.max_density));
  fog["waterz"] = Value(double(s.fog.water_z));
  x["fog"] = Value(std::move(fog));
  x["exposure"] = exposure_value(s.exposure);
  Value::Array zones;
  for (const ExposureZone& z : s.exposure_zones) {
    Value::Object o;
    o["min"] = floats(z.min);
    o["max"] = floats(z.max);
    o["exposure"] = exposure_value(z.exposure);
    zones.emplace_back(std::move(o));
  }
  x["exposurezones"] = Value(std::move(zones));
  Value::Array samples;
  for (const CubemapSample& c : s.cubemap_samples) {
    Value::Object o;
    o["position"] = floats(c.position);
    o["size"] = Value(c.size);
    samples.emplace_back(std::move(o));
  }
  x["cubemapsamples"] = Value(std::move(samples));
  Value::Array corrections;
  for (const ColorCorrection& c : s.color_corrections) corrections.push_back(color_correction_value(c));
  x["colorcorrections"] = Value(std::move(corrections));
  Value::Array volumes;
  for (const ColorCorrectionVolume& v : s.color_correction_volumes) {
    Value::Object o;
    o["lut"] = Value(v.lut);
    o["min"] = floats(v.min);
    o["max"] = floats(v.max);
    o["fadeduration"] = Value(double(v.fade_duration));
    volumes.emplace_back(std::move(o));
  }
  x["colorcorrectionvolumes"] = Value(std::move(volumes));
  if (s.irradiance_volume) {
    Value::Object v;
    v["min"] = floats(s.irradiance_volume->min);
    v["max"] = floats(s.irradiance_volume->max);
    v["spacing"] = floats(s.irradiance_volume->spacing);
    v["counts"] = floats(glm::vec3(s.irradiance_volume->counts));
    x["irradiancevolume"] = Value(std::move(v));
  }
  Value::Array path;
  for (const CameraKey& k : s.camera_path) {
    Value::Object o;
    o["time"] = Value(double(k.time));
    o["camera"] = camera_value(k.camera);
    path.emplace_back(std::move(o));
  }
  x["camerapath"] = Value(std::move(path));
  Value::Object extras;
  extras["luxel"] = Value(std::move(x));
  return Value(std::move(extras));
}

void read_scene_extras(const Value& extras, Scene& s, const std::function<void(const std::string&)>& fail) {
  const Value& x = extras.Get("luxel");
  if (!x.IsObject()) return;
  read(x.Get("background"), s.background);
  if (const Value& fog = x.Get("fog"); fog.IsObject()) {
    if (fog.Get("mode").IsString())
      for (const auto& [mode, name] : kFogModes)
        if (fog.Get("mode").Get<std::string>() == name) s.fog.mode = mode;
    read(fog.Get("color"), s.fog.color);
    read(fog.Get("start"), s.fog.start);
    read(fog.Get("end"), s.fog.end);
    read(fog.Get("maxdensity"), s.fog.max_density);
    read(fog.Get("waterz"), s.fog.water_z);
  }
  read_exposure(x.Get("exposure"), s.exposure);
  const Value& zones = x.Get("exposurezones");
  for (size_t i = 0; zones.IsArray() && i < zones.ArrayLen(); ++i) {
    const Value& o = zones.Get(int(i));
    ExposureZone z;
    read(o.Get("min"), z.min);
    read(o.Get("max"), z.max);
    read_exposure(o.Get("exposure"), z.exposure);
    s.exposure_zones.push_back(z);
  }
  const Value& samples = x.Get("cubemapsamples");
  for (size_t i = 0; samples.IsArray() && i < samples.ArrayLen(); ++i) {
    CubemapSample c;
    read(samples.Get(int(i)).Get("position"), c.position);
    read(samples.Get(int(i)).Get("size"), c.size);
    s.cubemap_samples.push_back(c);
  }
  const Value& corrections = x.Get("colorcorrections");
  for (size_t i = 0; corrections.IsArray() && i < corrections.ArrayLen(); ++i)
    s.color_corrections.push_back(read_color_correction(corrections.Get(int(i)), i, fail));
  const Value& volumes = x.Get("colorcorrectionvolumes");
  for (size_t i = 0; volumes.IsArray() && i < volumes.ArrayLen(); ++i) {
    const Value& o = volumes.Get(int(i));
    ColorCorrectionVolume v;
    if (o.Get("lut").IsString()) v.lut = o.Get("lut").Get<std::string>();
    read(o.Get("min"), v.min);
    read(o.Get("max"), v.max);
    read(o.Get("fadeduration"), v.fade_duration);
    s.color_correction_volumes.push_back(v);
  }
  if (const Value& v = x.Get("irradiancevolume"); v.IsObject()) {
    IrradianceVolume volume;
    read(v.Get("min"), volume.min);
    read(v.Get("max"), volume.max);
    read(v.Get("spacing"), volume.spacing);
    glm::vec3 counts(0.0f);
    read(v.Get("counts"), counts);
    volume.counts = glm::ivec3(counts);
    s.irradiance_volume = volume;
  }
  const Value& path = x.Get("camerapath");
  for (size_t i = 0; path.IsArray() && i < path.ArrayLen(); ++i) {
    CameraKey k;
    read(path.Get(int(i)).Get("time"), k.time);
    read_camera(path.Get(int(i)).Get("camera"), k.camera);
    s.camera_path.push_back(k);
  }
}

}  // namespace luxel::scenes::gltf
