// W4 `source`: not drawn by this program yet, and reported as skipped so that scripts/bench prints
// the comparison as not measured rather than a number that does not mean what it says.
//
// W4 is meant to be equal work to luxel's opaque pass: the same draws, combos and per-pixel
// arithmetic. luxel's renderer (frame/src/renderer.cpp) now draws the courtyard with combos that
// a port of the older definition would not: the hero through the skin path with per-vertex
// attenuation and an env map, the barrels and balls lit per vertex, the floor and walls split
// into one draw per cube-map sample their faces reflect. A port that stays equal has to follow
// the renderer's own choices: the frame library describing its opaque draws (mesh, family,
// combo, constants, textures) for this program to translate into GLSL, rather than a second copy
// of those rules here.

#include "workload_source.hpp"

namespace luxel::llvmpipe {

std::unique_ptr<Workload> make_source(const SourceOptions&, int, int) {
  throw Skipped("not ported yet: no GLSL port of luxel's opaque pass in this program");
}

}  // namespace luxel::llvmpipe
