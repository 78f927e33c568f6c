#pragma once
// The description of a .surf scene: the comment block at the top of the file (every
// examples/*.surf opens with one). Takes the file's text, puts out that block as one
// paragraph, and a one-line summary; both are empty when the file does not open with a
// comment.
#include <string>
#include <string_view>

namespace zs {

// The leading '#' lines, their '#' and surrounding blanks stripped, joined with spaces;
// blank lines before the first comment are skipped.
std::string sceneDescription(std::string_view text);

// The gallery's one-line form, when the file's first line has it (examples/README.md):
//   # NAME — degree D: ONE LINE        (also "degree D, N nodes", "not algebraic")
// that line without its '#'; otherwise the first sentence of the description (up to a '.'
// followed by a blank, or the end). Empty when there is no description.
std::string summaryLine(std::string_view text);

// `text` cut to at most `maxChars` code points, at a word when one is near, with "...".
std::string shortened(std::string_view text, std::size_t maxChars);

}  // namespace zs
