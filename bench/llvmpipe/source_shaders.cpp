// W4's GLSL. Each block names the luxel function it ports; the order of operations is luxel's, so
// that the two differ only where llvmpipe's arithmetic does (texture filtering, pow, the sRGB
// curve in float). sat, nrm and dxpow are DX9's saturate, nrm (nrm(0) = 0) and pow (|x|^y).

#include "source_shaders.hpp"

namespace luxel::llvmpipe {

namespace {

constexpr const char* kVertexShader = R"(#version 330 core
// Positions are in Source's world space already (luxel's import places every node), so the model
// matrix is the identity.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 tangent;  // xyz, w = handedness
layout(location = 3) in vec2 baseUv;   // the base texture's transform applied (CPU, per vertex)
layout(location = 4) in vec2 lightmapUv;
layout(location = 5) in vec4 color;
uniform mat4 viewProjection;
uniform vec4 fogZRow;  // the z row of the Direct3D projection x view: projected z for the fog
out vec3 vWorld;
out vec3 vNormal;
out vec3 vTangent;
out vec3 vBinormal;
out vec2 vBaseUv;
out vec2 vLightmapUv;
out vec4 vColor;
out float vProjZ;
void main() {
  vWorld = position;
  vNormal = normalize(normal);
  vTangent = normalize(tangent.xyz);
  vBinormal = tangent.w * cross(vNormal, vTangent);
  vBaseUv = baseUv;
  vLightmapUv = lightmapUv;
  vColor = color;
  vProjZ = dot(fogZRow, vec4(position, 1.0));
  gl_Position = viewProjection * vec4(position, 1.0);
}
)";

constexpr const char* kCommon = R"(
in vec3 vWorld;
in vec3 vNormal;
in vec3 vTangent;
in vec3 vBinormal;
in vec2 vBaseUv;
in vec2 vLightmapUv;
in vec4 vColor;
in float vProjZ;
out vec4 fragColor;

uniform float toneScale;  // c30.x, LINEAR_LIGHT_SCALE; c30.z (the env-map scale) is 1
uniform vec4 fogParams;   // x start / range, y water z, z max density, w 1 / range
uniform vec3 fogColor;    // linear, x the tone-map scale
uniform vec3 eyePosition;
uniform sampler2D baseTexture;

float sat(float x) { return clamp(x, 0.0, 1.0); }
vec3 sat(vec3 x) { return clamp(x, 0.0, 1.0); }
vec3 nrm(vec3 v) {
  float l2 = dot(v, v);
  return l2 > 0.0 ? v * inversesqrt(l2) : vec3(0.0);
}
float dxpow(float x, float y) { return pow(abs(x), y); }

// common.hpp final_output (linear tone map) and fog.hpp fogged_output, then the sRGB write
// D3D9 does (encode_srgb8).
vec4 final_output(vec3 c) {
  c *= toneScale;
#if defined(FOG_RANGE)
  float f = sat(min(fogParams.z, vProjZ * fogParams.w - fogParams.x));
  c = mix(c, fogColor, f * f);
#elif defined(FOG_HEIGHT)
  float throughWater = sat((fogParams.y - vWorld.z) * (1.0 / (eyePosition.z - vWorld.z)));
  c = mix(c, fogColor, sat(throughWater * vProjZ * fogParams.w));
#endif
  c = sat(c);
  vec3 lo = c * 12.92;
  vec3 hi = pow(c, vec3(1.0 / 2.4)) * 1.055 - 0.055;
  return vec4(mix(hi, lo, lessThanEqual(c, vec3(0.0031308))), 1.0);
}
)";

constexpr const char* kLightmappedGeneric = R"(
// lightmapped_generic.hpp: lightmapped_generic_fetch + lightmapped_generic_combine.
uniform sampler2D lightmapPage;  // flat, then the three bump maps, side by side
uniform vec4 lightmapOffset;     // where map k starts, in page u
uniform float lightmapScale;     // one map's width, in page u
uniform sampler2D bumpTexture;
uniform sampler2D maskTexture;
uniform samplerCube envmap;
uniform vec3 lightmapTint;       // c12.rgb: $color x the lightmap scale (1: float lightmaps)
uniform vec3 envmapTint;
uniform vec2 contrastSaturation;
uniform vec2 fresnel;            // (1 - R0, R0)

vec3 lightmap(int k) { return texture(lightmapPage, vec2(lightmapOffset[k] + lightmapScale * vLightmapUv.x, vLightmapUv.y)).rgb; }

void main() {
  vec4 base = texture(baseTexture, vBaseUv);
  vec3 n = vec3(0.0, 0.0, 1.0);
  vec3 diffuse;
#ifdef BUMP
  vec4 bump = texture(bumpTexture, vBaseUv);
  n = bump.xyz * 2.0 - 1.0;  // not renormalized
  // common.hpp rnm_weights, the SDK's basis literals
  vec3 d = vec3(sat(dot(n, vec3(0.81649661064147949, 0.0, 0.57735025882720947))),
                sat(dot(n, vec3(-0.40824833512306213, 0.70710676908493042, 0.57735025882720947))),
                sat(dot(n, vec3(-0.40824821591377258, -0.7071068286895752, 0.57735025882720947))));
  d = d * d;
  diffuse = d.x * lightmap(1) + d.y * lightmap(2) + d.z * lightmap(3);
  diffuse = diffuse * (lightmapTint / dot(d, vec3(1.0)));
#else
  diffuse = lightmap(0) * lightmapTint;
#endif
  vec3 color = base.rgb * diffuse;
#ifdef ENVMAP
#ifdef BUMP
  vec3 worldNormal = n.x * vTangent + n.y * vBinormal + n.z * vNormal;
#else
  vec3 worldNormal = vNormal;
#endif
  vec3 e = eyePosition - vWorld;
  vec3 r = (2.0 * dot(worldNormal, e)) * worldNormal - dot(worldNormal, worldNormal) * e;
  vec3 spec = texture(envmap, r).rgb;
#if defined(MASK_BASE_ALPHA)
  spec *= 1.0 - base.a;
#elif defined(MASK_NORMAL_ALPHA)
  spec *= bump.a;
#elif defined(MASK_TEXTURE)
  spec *= texture(maskTexture, vBaseUv).rgb;
#endif
  spec *= envmapTint;
#if defined(PATH_CONTRAST1)
  spec = spec * spec;
#elif defined(PATH_FULL)
  spec = mix(spec, spec * spec, contrastSaturation.x);
  float grey = dot(spec, vec3(0.299, 0.587, 0.114));
  spec = mix(vec3(grey), spec, contrastSaturation.y);
  float f = 1.0 - dot(worldNormal, nrm(e));
  spec *= dxpow(f, 5.0) * fresnel.x + fresnel.y;
#endif
  color += spec;
#endif
  fragColor = final_output(color);
}
)";

constexpr const char* kVertexLitGeneric = R"(
// vertexlit_generic.hpp: vertexlit_fetch + vertexlit_combine, attenuation per pixel, no env map.
uniform sampler2D bumpTexture;
uniform sampler2D exponentTexture;  // white when the material has none
uniform vec3 ambientCube[6];        // +X, -X, +Y, -Y, +Z, -Z
uniform vec4 lightColor[2];         // rgb; w = 1 directional
uniform vec4 lightPosition[2];      // w = 1; directional: toward the light, w = 0
uniform vec4 lightSpotDirection[2]; // w = 1 spot
uniform vec4 lightSpotParams[2];    // x exponent, z cos(outer), w 1 / (cos(inner) - cos(outer))
uniform vec4 lightAttenuation[2];   // constant, linear, quadratic
uniform vec4 modulation;            // $color, $alpha
uniform vec4 phongTintBoost;        // rgb tint (r < 0: the albedo tint), w $phongboost
uniform vec4 phongParams;           // x exponent (< 0: from the texture), y rim exponent, z rim boost, w rim mask
uniform vec4 shaderControls;        // x $basemapalphaphongmask, y the exponent texture's scale
uniform vec4 fresnelRanges;         // (2 (mid - min), mid, 2 (max - mid))

// common.hpp ambient_light
vec3 ambient_light(vec3 n) {
  vec3 n2 = n * n;
  bvec3 plus = greaterThanEqual(n, vec3(0.0));
  vec3 p = mix(vec3(0.0), n2, plus);
  vec3 m = mix(n2, vec3(0.0), plus);
  return p.x * ambientCube[0] + m.x * ambientCube[1] + p.y * ambientCube[2] + m.y * ambientCube[3] +
         p.z * ambientCube[4] + m.z * ambientCube[5];
}

// vertexlit_generic.hpp light_attenuation
float light_attenuation(int i, out vec3 toLight) {
  vec4 pos = lightPosition[i];
  vec3 v = pos.xyz - vWorld * pos.w;
  float d2 = dot(v, v);
  float d = sqrt(d2);
  toLight = nrm(v);
  float distance = 1.0 / dot(vec3(1.0, d, d2), lightAttenuation[i].xyz);
  float spot = (dot(lightSpotDirection[i].xyz, -toLight) - lightSpotParams[i].z) * lightSpotParams[i].w;
  spot = sat(dxpow(max(spot, 0.0001), lightSpotParams[i].x));
  float a = mix(distance, distance * spot, lightSpotDirection[i].w);
  return mix(a, 1.0, lightColor[i].w);
}

void main() {
  vec4 base = texture(baseTexture, vBaseUv);
  vec3 n;
#ifdef BUMP
  vec4 bump = texture(bumpTexture, vBaseUv);
  vec3 tn = bump.xyz * 2.0 - 1.0;
#ifdef PHONG
  tn = mix(tn, vec3(0.0, 0.0, 1.0), shaderControls.x);
#endif
  n = nrm(tn.x * vTangent + tn.y * vBinormal + tn.z * vNormal);
#else
  n = nrm(vNormal);
#endif
#if defined(PHONG) && defined(BUMP)
  vec4 exponentTexel = texture(exponentTexture, vBaseUv);
#else
  vec4 exponentTexel = vec4(1.0);
#endif
  vec3 diffuse = ambient_light(n);
  vec3 spec = vec3(0.0);
  vec3 rim = vec3(0.0);
#ifdef PHONG
  vec3 view = nrm(eyePosition - vWorld);
#ifdef BUMP
  float exponent = phongParams.x >= 0.0 ? phongParams.x : exponentTexel.x * shaderControls.y + 1.0;
#else
  float exponent = max(phongParams.x, 0.0);
#endif
#endif
  for (int i = 0; i < LIGHTS; ++i) {
    vec3 toLight;
    vec3 color = lightColor[i].rgb * light_attenuation(i, toLight);
    float nDotL = dot(n, toLight);
#ifdef HALF_LAMBERT
    float h = sat(nDotL * 0.5 + 0.5);
    diffuse += color * (h * h);
#else
    diffuse += color * sat(nDotL);
#endif
#ifdef PHONG
    vec3 r = (2.0 * dot(n, view)) * n - view;
    float rDotL = sat(dot(r, toLight));
    vec3 lit = color * sat(nDotL);
    spec += lit * dxpow(rDotL, exponent);
#ifdef RIM
    rim += lit * dxpow(rDotL, phongParams.y);
#endif
#endif
  }
  vec3 albedo = base.rgb * modulation.rgb;
  vec3 color = albedo * diffuse;
#ifdef PHONG
  float oneMinus = sat(1.0 - dot(n, view));
  float f = oneMinus * oneMinus;
  float g = f - 0.5;
  float fresnel = fresnelRanges.y + g * (g >= 0.0 ? fresnelRanges.z : fresnelRanges.x);
  float mask = base.a;
  vec3 tint = vec3(1.0);
#ifdef BUMP
  mask = mix(bump.a, base.a, shaderControls.x);
  tint = phongTintBoost.x >= 0.0 ? phongTintBoost.rgb : mix(vec3(1.0), base.rgb, exponentTexel.y);
#endif
  spec *= mask * fresnel * phongTintBoost.w;
#ifdef RIM
  float rimMask = mix(1.0, exponentTexel.w, phongParams.w);
  float m = rimMask * (f * f);
  spec = max(spec, rim * m);
  spec += ambient_light(view) * (phongParams.z * sat(m * n.z));
#endif
  color += spec * tint;
#endif
  fragColor = final_output(color);
}
)";

constexpr const char* kUnlitGeneric = R"(
// unlit_generic.hpp: unlit_generic_fetch + unlit_generic_combine (no detail texture).
uniform samplerCube envmap;
uniform sampler2D maskTexture;
uniform vec4 modulation;
uniform vec3 envmapTint;
uniform vec2 contrastSaturation;

void main() {
  vec4 base = texture(baseTexture, vBaseUv);
  vec3 color = base.rgb * modulation.rgb;
#ifdef VERTEX_COLOR
  color *= vColor.rgb;
#endif
#ifdef ENVMAP
  vec3 n = vNormal;
  vec3 e = eyePosition - vWorld;
  vec3 r = (2.0 * dot(n, e)) * n - dot(n, n) * e;
  vec3 spec = texture(envmap, r).rgb;
#if defined(MASK_TEXTURE)
  spec *= texture(maskTexture, vBaseUv).rgb;
#elif defined(MASK_BASE_ALPHA)
  spec *= 1.0 - base.a;
#endif
  spec *= envmapTint;
  spec = mix(spec, spec * spec, contrastSaturation.x);
  float grey = dot(spec, vec3(0.299, 0.587, 0.114));
  spec = mix(vec3(grey), spec, contrastSaturation.y);
  color += spec;
#endif
  fragColor = final_output(color);
}
)";

}  // namespace

const std::string& source_vertex_shader() {
  static const std::string source = kVertexShader;
  return source;
}

std::string source_fragment_shader(const std::string& defines) {
  std::string body;
  if (defines.find("#define LIGHTMAPPED_GENERIC") != std::string::npos)
    body = kLightmappedGeneric;
  else if (defines.find("#define VERTEXLIT_GENERIC") != std::string::npos)
    body = kVertexLitGeneric;
  else
    body = kUnlitGeneric;
  return "#version 330 core\n" + defines + kCommon + body;
}

}  // namespace luxel::llvmpipe
