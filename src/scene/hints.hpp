#pragma once
// "Did you mean" hints: takes a misspelled key or enum word, puts out a hint naming the
// closest valid spelling (by edit distance), or the list of valid choices when nothing is
// close.
#include <span>
#include <string>
#include <string_view>

namespace zs::scene_detail {

// Hint for an unknown dotted key: `did you mean "fov_y"?` (the sibling's short name when it
// lives in the same table, the full dotted name otherwise), or the keys valid in the table.
std::string unknownKeyHint(std::string_view dottedName);

// Hint for a word that is not one of `choices`.
std::string choiceHint(std::string_view word, std::span<const std::string_view> choices);

}  // namespace zs::scene_detail
