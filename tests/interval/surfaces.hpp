#pragma once
// The seven test surfaces of the thesis and the harder ones of the octree safety tests.
#include <array>
#include <string_view>

#include "expr/graph.hpp"

namespace zs::test {

inline constexpr std::array<std::string_view, 7> kThesisSurfaces = {
    "x^2+z^2-y",
    "x^2*y+x^2*z+y^2*x+y^2*z+z^2*y+z^2*x-(2/5)*(x*y+x*z+y*z)",
    "x^4+y^4+z^4-1",
    "x^2+y^3+z^5-1",
    "x^3*y+y^3*z+z^3*x",
    "x^4-z^4-y",
    "x^2*y^2+y^2*z^2+z^2*x^2-1",
};

// Parses a formula the test suite owns; a parse error is a bug in the test.
Formula parseOrDie(std::string_view text);

}  // namespace zs::test
