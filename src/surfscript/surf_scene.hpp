#pragma once
// A surf drawing as a zeroset Scene showing the same picture: surf's camera chain
// (origin, rot_*, scale_*, perspective) and its screen window (the shorter side of the
// picture spans -10..10) become a zeroset camera; where the chain is a rotation with a
// uniform scale, the camera turns and the formula stays as the script wrote it. The clip
// solid becomes the domain (and clip planes), surf's point lights and Phong weights
// zeroset's, and what zeroset cannot show the same way is said in a note.
#include <vector>

#include "scene/scene.hpp"
#include "surfscript/script_run.hpp"

namespace zs::surfscript {

// The scene of a draw_surface drawing (Drawing::Kind::Surfaces) at width x height. A
// drawing with no surface of degree 1 or more gives a scene whose formula is empty.
Scene surfaceScene(const Drawing& drawing, std::vector<Note>& notes);

}  // namespace zs::surfscript
