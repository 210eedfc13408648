#pragma once
// Textures and samplers: what a pixel shader's tex2D / texCUBE / tex3D read.
//
// A Texture holds 2D, cube or volume texels in their native format (no float32 expansion: a
// 1024x1024 RGBA8 texture with its mip chain is 5.6 MB), with every mip level in one allocation.
// A cube map keeps a second copy for sampling, each face level bordered by the texels across its
// edges (a little over twice the memory), so that seamless filtering reads plain rows. A small
// volume of one level (a color-correction LUT) keeps the eight texels of each trilinear footprint
// side by side (nine times the memory), so that a trilinear read under Clamp loads them at once.
// Sampling comes in two flavours that must agree:
//   - sample / sample_level / sample_grad: one stamp of simd::kLanes pixels at a time (the path
//     shaders use);
//   - sample_reference / lod_reference: one sample, plain scalar code written to be obviously
//     right, which the tests hold the SIMD path to.
// and follows one of two rule sets (Sampler::rules, "Sampling rules" below): the hardware rules,
// what DX9-era texture units did (the default), or the ideal rules, float filtering at full
// precision (the reference the hardware rules' error is measured against).
//
// The two flavours agree by construction where the conventions below fix float32 arithmetic
// (coordinate reduction, texel positions, filter weights, mip selection, cube face projection):
// both pick the same texels with the same weights. Under the hardware rules they agree to the bit
// (the reference does the same fixed-point and float32 steps). Under the ideal rules they differ
// only in how they filter (float32 FMA lerps vs double), by a few float32 ulps; point samples are
// exact in both. compute_lod is within ~1e-6 of lod_reference (a polynomial log2).
//
// A Texture is a value (copyable, movable). Sampling only reads it, from any number of threads;
// uploads and generate_mips() must not overlap sampling.
//
// Conventions. Direct3D's; where D3D9 left a choice to vendors, D3D10's rules.
//
// Texel addressing
// - Texel (i, j) of a W x H level covers [i, i+1) x [j, j+1) in texel space; normalized (u, v)
//   maps to (u W, v H), so texel centers sit at ((i + 0.5) / W, (j + 0.5) / H). Row 0 is the top
//   row (v = 0); in volumes slice 0 is at w = 0.
// - Point filtering reads texel floor(u W). Linear filtering reads the 2x2 (2x2x2 in volumes)
//   texels around u W - 0.5 and weighs them by the fractional part (as the sampling rules keep
//   it: 8 bits or all 23).
// - Address modes act per axis on every texel of the footprint (a footprint straddling an edge
//   wraps, mirrors or clamps texel by texel; under Border, texels outside the level read the
//   border color). Before scaling to texels, a coordinate is reduced to one period in float32:
//   c - floor(c) for Wrap, c - 2 floor(c / 2) for Mirror (both exact for |c| >= 1), so a
//   coordinate far from the origin keeps its sub-texel precision; Clamp and Border clamp c to
//   [-1, 2], which changes no result but keeps texel indices small. A NaN coordinate reads as 0;
//   an infinite one reads as 0 under Wrap and Mirror and as the nearest edge under Clamp/Border.
// - The border color is returned as given: linear, not quantized to the texture's format, not
//   sRGB-decoded, all four channels even for R32F.
//
// Formats (decoding happens before filtering, but for an sRGB read by the hardware rules)
// - UNORM channels (RGBA8, RGBA16) decode to c / (2^n - 1), correctly rounded.
// - RGBA8_sRGB decodes R, G, B with the exact sRGB curve (IEC 61966-2-1); alpha is linear. The
//   ideal rules decode before filtering, as D3D10 requires, the hardware rules after. An RGBA8
//   texture read with Sampler::srgb_read (D3D9's sampler state) decodes the same way.
// - RGBA16F decodes exactly (denormals, infinities and NaNs included).
// - R32F reads as (r, 1, 1, 1): D3D9's value for missing channels (Microsoft's "Recommended
//   DirectX 9.0 driver support": unused channels of R16F, G16R16F, R32F, G32R32F read 1.0). D3D10
//   would return (r, 0, 0, 1); our shaders are DX9 shaders.
// - Encoding (float uploads, mip generation) rounds to nearest even: UNORM stores
//   round(saturate(x) (2^n - 1)) (NaN stores 0); sRGB formats encode linear -> sRGB first; half
//   floats round like IEEE conversions (too large -> infinity).
//
// Level of detail
// - lod = log2(rho), rho = the larger of the lengths of d(u W, v H, w D)/dx and d(...)/dy, with
//   W, H, D the size of level 0: D3D's isotropic LOD. sample() takes the derivatives as coarse
//   per-quad differences (simd::ddx / simd::ddy), as DX9 hardware did.
// - For cube maps the derivatives are those of the face coordinates (u, v) of each lane's own face
//   (by the quotient rule: du = (d sc - (sc / |ma|) d|ma|) / (2 |ma|)), times the face size.
// - The LOD actually used is clamp(lod + shader bias + Sampler::lod_bias, min_lod, max_lod); a NaN
//   lod counts as 0. Up to 0 the texture is magnified (Sampler::mag), above 0 minified
//   (Sampler::min): OpenGL's crossover c = 0, which D3D does not spell out.
// - MipFilter::Point reads level floor(lod + 0.5) (a tie goes to the coarser level);
//   MipFilter::Linear blends levels floor(lod) and floor(lod) + 1 by the fraction;
//   MipFilter::None reads level 0. Levels clamp to [0, mip_levels - 1].
// - A sampler with MipFilter::None and the same min and mag filter gives the same result at every
//   LOD, so sample() does not compute one for it (the post-processing passes' samplers).
//
// Sampling rules (docs/fidelity.md#texture-sampling gives the sources)
// - SamplingRules::hardware, what the DX9-era texture units luxel reproduces did:
//   - one LOD per 2x2 quad: sample() gives every pixel of a quad its top-left pixel's LOD (from
//     the quad's coarse derivatives; for a cube map that pixel's face), plus the pixel's own bias
//     (sample_level and sample_grad take the LOD or derivatives they are given, per pixel);
//   - the LOD, after the biases and before the clamps, rounded to 8 fractional bits (to nearest,
//     ties to even), so the trilinear blend weight has 8 bits;
//   - texel positions in 16.8 fixed point: u W - 0.5 rounded to a multiple of 1/256 (to nearest,
//     ties to even); its integer part names the footprint's first texel, its 8 fractional bits
//     the second texel's weight w / 256 (D3D11's 8 bits of sub-texel precision);
//   - 8-bit UNORM texels filtered in fixed point: every blend of two values a, b (two texels of a
//     row, two rows, two slices, two levels) is a + floor(w (b - a) / 256 + 1/2), an integer again
//     (llvmpipe's rounding form for 8-bit formats); the filtered byte is then divided by 255. A
//     texel past a cube corner is the mean of the other three rounded the same way. An sRGB read
//     filters the encoded bytes so and decodes the filtered byte (after filtering, which D3D9
//     allowed; D3D10 asks for before). A border color is rounded to the format's 8-bit steps
//     (sRGB-encoded for an sRGB read).
//   - other formats (16-bit UNORM, half and single floats) blend in float32 with those weights.
// - SamplingRules::ideal: LOD per pixel (from the quad's coarse derivatives: the same within a
//   2D quad, per pixel for cube maps), unquantized LOD and weights, filtering in float32 (8-bit
//   texels as floats), sRGB decoded before filtering, the border color as given. What the rest of
//   this comment describes where it does not name a rule set.
//
// Cube maps
// - Face order +X, -X, +Y, -Y, +Z, -Z (D3DCUBEMAP_FACES). The face is the direction's major axis,
//   positive or negative by its sign (0 counts as positive). Ties break toward z, then y, then x
//   (|z| >= |x|, |y| picks a Z face; otherwise |y| >= |x| picks a Y face): the order llvmpipe
//   implements as D3D10's rule. With seamless linear filtering a tie only decides which of two
//   faces' coordinates name a point on their shared edge, so results agree up to rounding either
//   way; a fixed order keeps point samples on edges deterministic.
// - On face (sc, tc, ma): +X (-z, -y, x), -X (+z, -y, x), +Y (+x, +z, y), -Y (+x, -z, y),
//   +Z (+x, -y, z), -Z (-x, -y, z); u = (sc / |ma| + 1) / 2, v = (tc / |ma| + 1) / 2. This is the
//   layout of D3D's cube-map documentation (identical to OpenGL's table), v = 0 the top row.
//   The zero direction reads the center of +Z; a NaN or infinite component reads some texel of
//   some face (never outside the texture).
// - Filtering is seamless (D3D10 requires it; D3D9-era hardware clamped at each face's edges): a
//   footprint texel past a face's edge is read from the adjacent face; at a cube corner, where one
//   texel of the 2x2 footprint lies on no face, it is the average of the other three (the
//   ARB_seamless_cube_map recommendation, as llvmpipe does). Address modes do not apply.
//
// Mip levels
// - Level l is max(1, floor(size / 2^l)) on each axis (D3D); the full chain ends at 1x1(x1).
// - generate_mips() box-filters level l-1 into level l, per axis: an even size averages pairs; an
//   odd size n = 2m + 1 > 1 uses the exact area-weighted box (output texel i covers source texels
//   [i (2m+1)/m, (i+1)(2m+1)/m), i.e. texels 2i, 2i+1, 2i+2 weighted (m-i, m, i+1) / (2m+1)), so
//   every source texel contributes equally in total; a size of 1 is carried over. Filtering is
//   in linear float (sRGB decoded first, re-encoded after), rounding once per level.

#include "luxel/rasterizer/limits.hpp"
#include "luxel/rasterizer/simd.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace luxel::rasterizer {

/// Largest 2D texture and cube face, texels on a side (the D3D10 limit).
inline constexpr int kMaxTextureSize = kMaxTargetSize;
/// Largest volume texture, texels on a side (the D3D10 limit).
inline constexpr int kMaxVolumeSize = 2048;
/// Most mip levels of any texture (a full chain from kMaxTextureSize down to 1).
inline constexpr int kMaxMipLevels = 14;
static_assert((kMaxTextureSize >> (kMaxMipLevels - 1)) == 1, "a full chain of the largest texture");
static_assert(kMaxVolumeSize <= kMaxTextureSize);
/// Most words a volume's trilinear cells may take (16 MiB: a 100^3 volume; a LUT has at most 64
/// points per axis); a larger volume is read without them.
inline constexpr int64_t kMaxCellWords = int64_t{1} << 22;

enum class TextureFormat : uint8_t {
  RGBA8,       ///< 4 x 8-bit UNORM, bytes R, G, B, A (DXGI R8G8B8A8_UNORM, D3DFMT_A8B8G8R8)
  RGBA8_sRGB,  ///< RGBA8 whose R, G, B are sRGB-encoded (decoded on read)
  RGBA16F,     ///< 4 x IEEE half, R, G, B, A (D3DFMT_A16B16G16R16F): HDR lightmaps, cube maps
  RGBA16,      ///< 4 x 16-bit UNORM, R, G, B, A (D3DFMT_A16B16G16R16)
  R32F,        ///< 1 x float (D3DFMT_R32F); reads as (r, 1, 1, 1)
};

enum class TextureKind : uint8_t { Texture2D, Cube, Volume };

/// Cube faces in D3D order (D3DCUBEMAP_FACES); the value is the face index.
enum class CubeFace : uint8_t { PositiveX, NegativeX, PositiveY, NegativeY, PositiveZ, NegativeZ };

/// Bytes of one texel of `format` (4, 4, 8, 8, 4).
int bytes_per_texel(TextureFormat format);

/// What to create. Texture::create checks every field.
struct TextureDesc {
  TextureKind kind = TextureKind::Texture2D;
  TextureFormat format = TextureFormat::RGBA8;
  int width = 0, height = 0;
  int depth = 1;       ///< volumes only; 1 otherwise
  int mip_levels = 0;  ///< 0 = the full chain down to 1x1(x1)
};

class Texture {
 public:
  static constexpr int kFullMipChain = 0;

  /// Throws std::invalid_argument with a message naming the problem: a size of 0 or less, above
  /// kMaxTextureSize (kMaxVolumeSize for volumes), a cube whose width != height, a depth other than
  /// 1 for a 2D texture or cube, a mip count below 0 or above the full chain's.
  static Texture create(const TextureDesc& desc);
  static Texture create_2d(int width, int height, TextureFormat format, int mip_levels = kFullMipChain);
  static Texture create_cube(int size, TextureFormat format, int mip_levels = kFullMipChain);
  static Texture create_volume(int width, int height, int depth, TextureFormat format,
                               int mip_levels = kFullMipChain);

  TextureKind kind() const { return kind_; }
  TextureFormat format() const { return format_; }
  /// Size of `level` (max(1, size0 >> level)).
  int width(int level = 0) const { return level_size(width_, level); }
  int height(int level = 0) const { return level_size(height_, level); }
  int depth(int level = 0) const { return level_size(depth_, level); }
  int mip_levels() const { return levels_; }
  /// 6 for cube maps, 1 otherwise.
  int faces() const { return kind_ == TextureKind::Cube ? 6 : 1; }
  /// Number of mip levels of a full chain for these sizes.
  static int full_mip_chain(int width, int height, int depth = 1);

  /// The texels of one level of one face, tightly packed: rows top to bottom, then slices front
  /// to back, each texel as bytes_per_texel(format()) bytes in the format's channel order.
  /// Throws std::out_of_range for a level or face that does not exist.
  std::span<const uint8_t> level_bytes(int level, int face = 0) const;
  /// Bytes held: all levels of all faces, the padding after them (words_), and a cube map's or a
  /// volume's second copy for sampling (below).
  size_t storage_bytes() const { return (words_.size() + cube_words_.size() + cell_words_.size()) * sizeof(uint32_t); }

  /// Replaces one level of one face with `bytes`, laid out as level_bytes() describes. Throws
  /// std::invalid_argument when the size does not match, std::out_of_range for a bad level/face.
  void upload(int level, std::span<const uint8_t> bytes, int face = 0);
  /// Same, from linear float RGBA texels (encoded as the header's conventions say; R32F keeps r).
  void upload(int level, std::span<const glm::vec4> texels, int face = 0);
  /// Fills levels 1.. of every face from level 0 (box filter; see "Mip levels" above).
  void generate_mips();

  /// Every texel of every level and face has alpha at its format's maximum (255, 65535, half 1.0;
  /// R32F always): sampling then filters the color channels alone and returns alpha 1, exactly
  /// what filtering the constant alpha gives, for less work. Kept current by upload and
  /// generate_mips; a new texture (all zero) is not opaque, but for R32F.
  bool opaque() const { return opaque_; }

  /// One texel, decoded to float RGBA (sRGB decoded, R32F as (r, 1, 1, 1)), no filtering (D3D10's
  /// Load). For cube maps `z` is the face. Throws std::out_of_range outside the texture.
  glm::vec4 load(int x, int y, int z = 0, int level = 0) const;

 private:
  friend struct TextureAccess;
  Texture() = default;
  static int level_size(int size0, int level) { return size0 >> level > 1 ? size0 >> level : 1; }
  void check_level_face(int level, int face) const;
  size_t level_words(int level) const;
  std::span<uint8_t> level_span(int level, int face);
  /// Remakes the sampling copy of a cube map's `level` after `face` changed (all faces: -1).
  void refresh_cube_copy(int level, int face);
  /// Remakes a volume's trilinear cells (if it keeps them) from its texels.
  void refresh_cells();
  /// Records whether `level` of `face` is opaque, and opaque_ with it.
  void set_level_opaque(int level, int face, bool opaque);
  /// Whether every texel of `texels` (whole texels of this format) has alpha at its maximum.
  bool alpha_at_max(std::span<const uint8_t> texels) const;

  TextureKind kind_ = TextureKind::Texture2D;
  TextureFormat format_ = TextureFormat::RGBA8;
  int width_ = 0, height_ = 0, depth_ = 1, levels_ = 0;
  int words_per_texel_ = 1;
  /// Storage is face-major: face f, level l starts at word f * face_words_ + level_offset_[l].
  /// Offsets are in 32-bit words and fit int32 (checked at creation), so SIMD gathers can index
  /// any texel of any level from one base pointer. words_ ends with simd::kStampRowWindowWords
  /// words of padding past the last face.
  int32_t face_words_ = 0;
  std::array<int32_t, kMaxMipLevels> level_offset_{};
  std::vector<uint32_t> words_;
  /// Cube maps only: a second copy that sampling reads, each face level n x n stored as
  /// (n + 2) x (n + 2) with a one-texel border holding the texels across its edges on the
  /// neighbouring faces (the seamless filter's), so that a bilinear footprint never leaves its
  /// face's rows; the four corner texels, past two edges, hold 0 (the filter replaces them).
  /// Same face-major layout as words_; made again by every upload and generate_mips().
  int32_t cube_face_words_ = 0;
  std::array<int32_t, kMaxMipLevels> cube_level_offset_{};
  std::vector<uint32_t> cube_words_;
  /// Volumes of one level and a one-word format, up to kMaxCellWords: for each trilinear
  /// footprint's square in a slice, its four texels side by side (x fastest, then y), which a
  /// read under Clamp loads at once, and the square above it in the next slice (simd::
  /// gather_two_fours), instead of gathering them texel by texel. Along an axis of n texels the
  /// footprint starting at texel i, for i in [-1, n - 1], reads texels clamp(i) and clamp(i + 1):
  /// a footprint past an edge repeats the edge's texels as Clamp does, and one further out reads
  /// the same as the one at -1 or n - 1. Square (i, j) of slice k, for k in [-1, n] (slice k
  /// holds texels of slice clamp(k)), starts at word 4 (((k + 1)(h + 1) + j + 1)(w + 1) + i + 1).
  /// Squares rather than whole cubes of eight: half the memory, for the same loads of a lane.
  /// Made again by every upload.
  std::vector<uint32_t, xsimd::aligned_allocator<uint32_t, 64>> cell_words_;
  /// Per face and level (face-major): whether its alpha is at the maximum everywhere.
  std::vector<uint8_t> level_opaque_;
  bool opaque_ = false;  ///< all of level_opaque_ (read by every sample)
};

enum class Filter : uint8_t { Point, Linear };
/// How texels are filtered: see "Sampling rules" above.
enum class SamplingRules : uint8_t {
  hardware,  ///< DX9-era texture units: LOD per quad, 8-bit weights, fixed-point 8-bit filtering
  ideal,     ///< full float precision, LOD per pixel: the reference the hardware rules are measured against
};
enum class MipFilter : uint8_t { None, Point, Linear };
enum class Address : uint8_t { Wrap, Mirror, Clamp, Border };

/// How a texture is read (D3D9 sampler states, D3D10 float LOD clamps). Defaults: trilinear and
/// wrap, what Source materials ask for (D3D9's own defaults are point filtering and no mips).
struct Sampler {
  Filter min = Filter::Linear;  ///< when minified (LOD > 0)
  Filter mag = Filter::Linear;  ///< when magnified (LOD <= 0)
  MipFilter mip = MipFilter::Linear;
  Address u = Address::Wrap, v = Address::Wrap, w = Address::Wrap;  ///< ignored by cube maps
  glm::vec4 border{0.0f};  ///< Address::Border color, linear (D3D9's default is 0)
  float lod_bias = 0.0f;   ///< D3DSAMP_MIPMAPLODBIAS
  float min_lod = 0.0f;    ///< the most detailed LOD allowed (D3D9 MAXMIPLEVEL, as a float)
  float max_lod = std::numeric_limits<float>::max();
  /// D3DSAMP_SRGBTEXTURE: an RGBA8 texture's R, G, B are decoded from sRGB on read, exactly as
  /// RGBA8_sRGB's are. D3D9 made sRGB decode a sampler state, so one texture can be read both
  /// ways (the engine's _rt_FullFrameFB: sRGB by the luminance histogram, gamma values by bloom
  /// and color correction). An RGBA8_sRGB texture, whose mips were made in linear, is decoded
  /// either way; other formats ignore it.
  bool srgb_read = false;
  SamplingRules rules = SamplingRules::hardware;
};

/// Per-lane texture coordinates as the shader passes them: (u, v) for 2D textures (z unused),
/// (u, v, w) for volumes, a direction (not necessarily normalized) for cube maps.
struct TexCoord {
  simd::Float x, y, z;
};

/// Samples one stamp with the LOD computed per quad from the coordinates' coarse derivatives
/// (tex2D / texCUBE / tex3D), plus a per-lane `bias` (tex2Dbias). Returns linear RGBA in
/// x, y, z, w.
simd::Float4 sample(const Texture& texture, const Sampler& sampler, const TexCoord& coord,
                    const simd::Float& bias = simd::Float(0.0f));
/// What `coords.size()` sample() calls of one sampler return, into `out` (as many): several taps of
/// one texture per pixel, as a blur's. A sampler that needs no LOD (no mips, one filter: the post
/// passes') reads a 2D texture's taps in one call, its decisions and the level's geometry made
/// once (the same results to the bit).
void sample_taps(const Texture& texture, const Sampler& sampler, std::span<const TexCoord> coords,
                 std::span<simd::Float4> out);
/// Samples at an explicit per-lane LOD (tex2Dlod); the sampler's bias and clamps still apply.
simd::Float4 sample_level(const Texture& texture, const Sampler& sampler, const TexCoord& coord,
                          const simd::Float& lod);
/// Samples with explicit derivatives of the coordinates along screen x and y (tex2Dgrad).
simd::Float4 sample_grad(const Texture& texture, const Sampler& sampler, const TexCoord& coord,
                         const TexCoord& ddx, const TexCoord& ddy);
/// The LOD those derivatives give, before bias and clamps (HLSL CalculateLevelOfDetailUnclamped).
/// -inf for zero derivatives.
simd::Float compute_lod(const Texture& texture, const TexCoord& coord, const TexCoord& ddx,
                        const TexCoord& ddy);

/// Scalar reference of sample_level: one sample at `coord` ((u, v, -) for 2D, (u, v, w) for
/// volumes, a direction for cubes) and `lod` (before the sampler's bias and clamps). Plain code,
/// float32 where the conventions above fix the float32 arithmetic (coordinate reduction, texel
/// positions, filter weights, face projection), double everywhere else.
glm::vec4 sample_reference(const Texture& texture, const Sampler& sampler, glm::vec3 coord, float lod);
/// Scalar reference of compute_lod, in double, from explicit derivatives.
float lod_reference(const Texture& texture, glm::vec3 coord, glm::vec3 ddx, glm::vec3 ddy);

/// Where a direction lands on a cube: its face and the face coordinates in [0, 1].
struct CubeFaceCoord {
  CubeFace face;
  float u, v;
};
/// Face selection and projection, by the conventions above.
CubeFaceCoord cube_face(glm::vec3 direction);
/// The inverse: the (unnormalized, major axis +-1) direction through (u, v) of `face`.
glm::vec3 cube_direction(CubeFace face, float u, float v);

}  // namespace luxel::rasterizer
