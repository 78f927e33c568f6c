#pragma once
// The description of a .surf scene: the comment block at the top of the file (every
// examples/*.surf opens with one). Takes the file's text, puts out that block as one
// paragraph, and its first sentence as a one-line summary; both are empty when the file
// does not open with a comment.
#include <string>
#include <string_view>

namespace zs {

// The leading '#' lines, their '#' and surrounding blanks stripped, joined with spaces;
// blank lines before the first comment are skipped.
std::string sceneDescription(std::string_view text);

// The first sentence of `description` (up to a '.' followed by a blank, or the end),
// shortened to at most `maxChars` code points with "..." when longer.
std::string summaryLine(std::string_view description, std::size_t maxChars = 100);

}  // namespace zs
