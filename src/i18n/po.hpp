#pragma once
// Reads a gettext .po file (the translators' format: msgid/msgstr pairs, continued strings,
// C escapes, comments and flags). A message marked `#, fuzzy` or with an empty msgstr is
// left out, as msgfmt leaves it out: the English text is shown instead. Plural forms and
// contexts are not used by zeroset's messages and are refused, so a file that needs them
// fails loudly rather than being half read.
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <variant>

namespace zs::i18n {

// Looks strings up by string_view, so a translation is found without building a string
// (the viewer asks for every label of its panel each frame).
struct StringHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
};
template <class Value>
using StringMap = std::unordered_map<std::string, Value, StringHash, std::equal_to<>>;

struct Catalog {
  std::string language;             // from the header's "Language:" line ("es"); "" when absent
  StringMap<std::string> messages;  // English -> translation
};

struct PoError {
  int line = 0;  // 1-based
  std::string message;
};

std::variant<Catalog, PoError> parsePo(std::string_view text);

}  // namespace zs::i18n
