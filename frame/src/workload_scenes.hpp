#pragma once
// Private: the factories behind make_builtin_scene.

#include "luxel/frame/builtin.hpp"

namespace luxel::frame {
std::unique_ptr<BuiltinScene> make_fill_scene(const FrameSettings& s);
std::unique_ptr<BuiltinScene> make_tris_scene(const FrameSettings& s);
std::unique_ptr<BuiltinScene> make_demo_scene(const FrameSettings& s);
}  // namespace luxel::frame
