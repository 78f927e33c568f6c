#pragma once
// SurferScene <-> zeroset Scene: the frame (surfer_frame.hpp), the lighting (lighting.hpp)
// and the settings SURFER does not have. An imported scene looks like SURFER's picture: a
// square image, no silhouette or border lines, no reflection, 2 x 2 supersampling.
#include <string>
#include <vector>

#include "jsurf/surfer_scene.hpp"
#include "scene/scene.hpp"

namespace zs::jsurf {

Scene toScene(const SurferScene& surfer, std::vector<std::string>& notes);

// The clipping sphere must be centred at the origin (SURFER's always is): a box domain
// becomes the ball around it, a centre elsewhere is dropped, each with a note.
SurferScene toSurferScene(const Scene& scene, std::vector<std::string>& notes);

}  // namespace zs::jsurf
