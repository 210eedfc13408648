// What a frame reports of the shaders it ran (shader_use.hpp).

#include "luxel/shading/source/shader_use.hpp"

#include <algorithm>

namespace luxel::shading::source {

void add_shader_use(std::vector<ShaderUse>& uses, const ShaderUse& use) {
  const auto same = std::find_if(uses.begin(), uses.end(),
                                 [&](const ShaderUse& u) { return u.family == use.family && u.combo == use.combo; });
  if (same == uses.end()) uses.push_back(use);
  else same->pixels += use.pixels;
}

}  // namespace luxel::shading::source
