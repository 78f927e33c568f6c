#pragma once
// The translations of po/*.po, built into the program by cmake/EmbedCatalogs.cmake.
#include <span>
#include <string_view>

namespace zs::i18n {

struct EmbeddedCatalog {
  std::string_view code;  // the file's name: po/es.po is "es"
  std::string_view name;  // the language's own name, from the file's "X-Language-Name" header
  std::string_view text;  // the whole .po file
};

std::span<const EmbeddedCatalog> embeddedCatalogs();

}  // namespace zs::i18n
