#pragma once
// The reading half of the import: .jsurf text -> SurferScene, with every key checked where
// it stands (file:line:column). Unknown keys, keys SURFER itself ignores and values zeroset
// must bend (a colour above 1) are warnings; what SURFER could not load either (no
// formula, a formula that does not parse, a word that is not ON or OFF, a matrix that is
// not 16 numbers or cannot be inverted) is an error.
#include <string_view>
#include <variant>
#include <vector>

#include "jsurf/surfer_scene.hpp"
#include "scene/scene_io.hpp"

namespace zs::jsurf {

struct SurferRead {
  SurferScene scene;
  std::vector<SceneError> warnings;
};

std::variant<SurferRead, SceneError> readSurferScene(std::string_view text,
                                                     std::string_view fileName);

// Every key SURFER reads (parameters excepted), for hints and the documentation test.
const std::vector<std::string>& surferKeys();

}  // namespace zs::jsurf
