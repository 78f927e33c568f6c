#pragma once
// SurferScene -> .jsurf text, with the keys SURFER itself writes (rotation_matrix and
// scale_factor for the view, not jsurf's transform_matrix) and numbers in the shortest form
// that reads back to the same double.
#include <string>

#include "jsurf/surfer_scene.hpp"

namespace zs::jsurf {

std::string writeSurferScene(const SurferScene& scene);

}  // namespace zs::jsurf
