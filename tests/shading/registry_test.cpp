// The registry of Source combos (shading/source/registry.hpp) and the catalog built from it: each
// space follows the SDK's SKIP rules and helper choices (docs/fidelity.md), every combo appears in
// the catalog once, counted, with SIMD and scalar entry points that agree.

#include "luxel/shading/source/catalog.hpp"
#include "luxel/shading/source/registry.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace luxel::shading::source {
namespace {

template <class Space>
std::set<std::string> names_of(const Space& space) {
  std::set<std::string> names;
  for (const auto& c : space) names.insert(c.name());
  return names;
}

template <class Space>
void expect_unique_and_valid(const Space& space, const char* family) {
  EXPECT_EQ(names_of(space).size(), space.size()) << family << ": every combo once (names are unique per combo)";
  for (const auto& c : space) EXPECT_TRUE(on_some_model(c)) << family << " " << c.name();
}

TEST(Registry, EverySpaceListsEachCombosOnceAndOnlyCombosSomeBinaryAllows) {
  expect_unique_and_valid(kLightmappedSpace, "LightmappedGeneric");
  expect_unique_and_valid(kVertexLitSpace, "VertexLitGeneric");
  expect_unique_and_valid(kUnlitSpace, "UnlitGeneric");
  expect_unique_and_valid(kWaterSpace, "Water");
  std::printf("registry: LightmappedGeneric %zu, VertexLitGeneric %zu (+ vertex shader %zu), UnlitGeneric %zu, Water %zu, "
              "Sky_HDR %zu combos\n",
              kLightmappedSpace.size(), kVertexLitSpace.size(), kVertexLitVsSpace.size(), kUnlitSpace.size(),
              kWaterSpace.size(), kSkySpace.size());
}

TEST(Registry, LightmappedSpaceIsTheSdksCombosOverLuxelsSwitches) {
  // Counted from lightmappedgeneric_ps2_3_x.h's rules, apart from valid(): without an env map one
  // combo per bump choice; with one, flat surfaces take no mask, base alpha or $envmapmask, bumped
  // ones no mask or the normal map's alpha (SKIP $BASEALPHAENVMAPMASK && $BUMPMAP; the helper
  // drops $envmapmask with a bump map), each on three paths; every one of them with four fogs.
  // Allowing the skipped bump + base-alpha combo gives 80.
  constexpr size_t kUnfogged = 2 + (3 + 2) * 3;
  EXPECT_EQ(kLightmappedSpace.size(), kUnfogged * 4);
  for (const LightmappedCombo& c : kLightmappedSpace)
    EXPECT_FALSE(c.bump && c.mask == EnvmapMask::base_alpha_inverted) << c.name();
}

TEST(Registry, VertexLitSpaceHasTheSdksPerPixelPathsOnly) {
  int skin = 0, bumped = 0, four_lights = 0, cube = 0;
  for (const VertexLitCombo& c : kVertexLitSpace) {
    // Without a bump map or Phong the SDK lights per vertex (kUnlitSpace's DIFFUSELIGHTING).
    EXPECT_TRUE(c.bump || c.phong) << c.name();
    EXPECT_FALSE(c.sh9_ambient) << c.name() << ": SH9 is measured in the report, not an SDK binary";
    // skin_ps20b.fxc: SKIP $FASTPATH_NOBUMP && $RIMLIGHT; the skin shader always takes Half-Lambert.
    if (c.rim) EXPECT_TRUE(c.bump && c.phong) << c.name();
    if (c.phong) EXPECT_TRUE(c.half_lambert) << c.name();
    // vertexlit_and_unlit_generic_bump_ps2x.fxc: SKIP $NORMALMAPALPHAENVMAPMASK && !$CUBEMAP.
    if (c.envmap_normal_alpha) EXPECT_TRUE(c.envmap && c.bump && !c.phong) << c.name();
    skin += c.phong;
    bumped += c.bump && !c.phong;
    four_lights += c.lights == 4;
    cube += c.normalization_cube;
  }
  EXPECT_GT(skin, 0);
  EXPECT_GT(bumped, 0);
  EXPECT_GT(four_lights, 0);
  EXPECT_GT(cube, 0);
  // The skin shader exists only as ps20b and ps30: no ps_2_0 combo (normalization cube) of it.
  for (const VertexLitCombo& c : kVertexLitSpace)
    if (c.phong) EXPECT_FALSE(c.normalization_cube) << c.name();
}

TEST(Registry, CountingOutsideASpaceIsAnError) {
  EXPECT_THROW(counted_cost(VertexLitCombo{2, false, false, false, true, true}, ShaderModel::ps_2_b), std::logic_error);
  EXPECT_THROW(counted_cost(LightmappedCombo{true, true, EnvmapMask::base_alpha_inverted}, ShaderModel::ps_2_b),
               std::logic_error);
  EXPECT_FALSE(vertexlit_fits(VertexLitCombo{2, false, false, false, true, true}, ShaderModel::ps_2_b));
}

TEST(Registry, TheCatalogListsEveryComboOnceWithItsCount) {
  std::map<std::string, std::set<std::string>> variants;
  size_t rows = 0;
  for (const ShaderVariant& v : shader_catalog()) {
    variants[v.family].insert(v.variant);
    ++rows;
    ASSERT_NE(v.shade_simd, nullptr) << v.family << " " << v.variant;
    ASSERT_NE(v.shade_scalar, nullptr) << v.family << " " << v.variant;
    for (ShaderModel card : v.models) {
      const std::optional<ShaderModel> binary = v.builds.binary_for(card);
      ASSERT_TRUE(binary) << v.family << " " << v.variant;
      EXPECT_GT(v.measure(*binary).total_slots(), 0) << v.family << " " << v.variant;
    }
  }
  EXPECT_EQ(variants["LightmappedGeneric"], names_of(kLightmappedSpace));
  EXPECT_EQ(variants["Water"], names_of(kWaterSpace));
  EXPECT_EQ(variants["Sky_HDR"], names_of(kSkySpace));
  EXPECT_EQ(variants["VertexLitGeneric_vs"], names_of(kVertexLitVsSpace));
  // VertexLitGeneric: the per-pixel combos and the DIFFUSELIGHTING ones of the unlit source.
  std::set<std::string> vertexlit = names_of(kVertexLitSpace), unlit;
  for (const UnlitCombo& c : kUnlitSpace) (c.diffuse_lighting ? vertexlit : unlit).insert(c.name());
  EXPECT_EQ(variants["VertexLitGeneric"], vertexlit);
  EXPECT_EQ(variants["UnlitGeneric"], unlit);
  // The post shaders: the combos of their spaces and the four without static combos.
  const size_t post = kLuminanceRangeSpace.size() + kColorCorrectionSpace.size() + kEnginePostSpace.size() + 4;
  EXPECT_EQ(rows, kLightmappedSpace.size() + kVertexLitSpace.size() + kVertexLitVsSpace.size() + kUnlitSpace.size() +
                      kWaterSpace.size() + kSkySpace.size() + post);
}

TEST(Registry, EveryVariantsSimdEntryGivesItsScalarEntrysBits) {
  // The ps_2_0 combos read the normalization cube in their combine stage: there the scalar lane's
  // reference sampler (double) and the SIMD sampler (float) may differ by a rounding, within a step.
  int compared = 0;
  for (const ShaderVariant& v : shader_catalog()) {
    const bool samples_cube = v.variant.find("+normcube") != std::string::npos;
    for (LaneInputs inputs : {LaneInputs::timing, LaneInputs::hard}) {
      const LaneAgreement a = compare_lanes(v, 256, inputs);
      const char* kind = inputs == LaneInputs::hard ? " (hard inputs)" : "";
      if (samples_cube) {
        EXPECT_LE(a.max_steps, 1) << v.family << " " << v.variant << kind;
      } else {
        EXPECT_EQ(a.differing, 0u) << v.family << " " << v.variant << kind << ": max |diff| " << a.max_abs;
      }
    }
    ++compared;
  }
  EXPECT_EQ(size_t(compared), shader_catalog().size());
}

}  // namespace
}  // namespace luxel::shading::source
