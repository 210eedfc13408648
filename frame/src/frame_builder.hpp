#pragma once
// Turns a view of the scene into its draws: every mesh's material through the shader families'
// combo choice (renderer.hpp promises what each family is drawn with), the sky, and the water's
// surface; translucent draws sorted back to front.

#include "frame_state.hpp"
#include "views.hpp"

namespace luxel::frame {

/// Appends the draws of `view` to `out` (its passes), recording the data they point at in `st`.
void build_view(FrameState& st, const ViewSpec& view, PassList& out);

}  // namespace luxel::frame
