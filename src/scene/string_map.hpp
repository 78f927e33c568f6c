#pragma once
// Where each byte of a TOML string's value was read from: takes the source text, the offset
// of the string's opening quote and the decoded value, and returns for each value byte (plus
// one past the end) its source offset. A formula error's byte span then lands on the right
// line and column of the file, across escapes (\t, \u00e9: every byte of an escape maps to
// its backslash), line-ending backslashes and multi-line strings.
#include <cstddef>
#include <string_view>
#include <vector>

namespace zs::scene_detail {

std::vector<std::size_t> stringSourceMap(std::string_view text, std::size_t quoteOffset,
                                         std::string_view value);

}  // namespace zs::scene_detail
