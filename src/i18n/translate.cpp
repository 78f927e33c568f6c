#include "i18n/translate.hpp"

#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <stdexcept>
#include <variant>
#include <vector>

#include "i18n/embedded_catalogs.hpp"
#include "i18n/po.hpp"

namespace zs::i18n {
namespace {

struct Loaded {
  std::vector<Language> languages;
  std::map<std::string, Catalog, std::less<>> catalogs;  // by code
};

// The built-in catalogs, parsed once. A catalog that does not parse is a build defect
// (tests/i18n parses every one), so it is an exception, not a silent English fallback.
const Loaded& loaded() {
  static const Loaded all = [] {
    Loaded l;
    l.languages.push_back({"en", "English"});
    for (const EmbeddedCatalog& e : embeddedCatalogs()) {
      auto parsed = parsePo(e.text);
      if (auto* error = std::get_if<PoError>(&parsed))
        throw std::logic_error("po/" + std::string(e.code) + ".po:" + std::to_string(error->line) +
                               ": " + error->message);
      l.catalogs.emplace(std::string(e.code), std::move(std::get<Catalog>(parsed)));
      l.languages.push_back({e.code, e.name});
    }
    return l;
  }();
  return all;
}

struct State {
  std::mutex mutex;
  std::string_view code = "en";
  const Catalog* catalog = nullptr;
  StringMap<std::string> labels;  // of the current language
};

State& state() {
  static State s;
  return s;
}

}  // namespace

std::span<const Language> languages() {
  return loaded().languages;
}

namespace {

// The language a tag names ("es_ES.UTF-8", "de-AT", "ES"), or nothing.
const Language* findLanguage(std::string_view tag) {
  std::string code;
  for (char c : tag) {
    if (c == '_' || c == '-' || c == '.' || c == '@') break;
    code += char(std::tolower(static_cast<unsigned char>(c)));
  }
  for (const Language& l : languages())
    if (l.code == code) return &l;
  return nullptr;
}

}  // namespace

std::string knownLanguage(std::string_view tag) {
  const Language* l = findLanguage(tag);
  return l ? std::string(l->code) : std::string();
}

std::string languageFromEnvironment() {
  // The locale of messages: LC_ALL, else LC_MESSAGES, else LANG; none is "C".
  std::string_view locale = "C";
  for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"})
    if (const char* v = std::getenv(name); v && *v) {
      locale = v;
      break;
    }
  // LANGUAGE is a priority list ("de:en") that gettext reads only when the locale is not
  // "C" (or "POSIX"), which asks for the program's own texts.
  const bool plain = locale == "C" || locale == "POSIX" || locale.substr(0, 2) == "C.";
  if (const char* list = std::getenv("LANGUAGE"); list && *list && !plain) {
    std::string_view rest(list);
    while (!rest.empty()) {
      const std::size_t colon = rest.find(':');
      const std::string code = knownLanguage(rest.substr(0, colon));
      if (!code.empty()) return code;
      if (colon == std::string_view::npos) break;
      rest.remove_prefix(colon + 1);
    }
  }
  const std::string code = plain ? "" : knownLanguage(locale);
  return code.empty() ? "en" : code;
}

bool setLanguage(std::string_view tag) {
  const Language* language = findLanguage(tag);
  if (!language) return false;
  State& s = state();
  std::lock_guard lock(s.mutex);
  if (s.code == language->code) return true;
  s.code = language->code;  // a view into languages(), which lives as long as the program
  const auto& catalogs = loaded().catalogs;
  const auto it = catalogs.find(language->code);
  s.catalog = it == catalogs.end() ? nullptr : &it->second;
  s.labels.clear();
  return true;
}

std::string_view currentLanguage() {
  State& s = state();
  std::lock_guard lock(s.mutex);
  return s.code;
}

namespace {

const char* translated(const State& s, const char* english) {
  if (!s.catalog) return english;
  const auto it = s.catalog->messages.find(std::string_view(english));
  return it == s.catalog->messages.end() ? english : it->second.c_str();
}

}  // namespace

const char* tr(const char* english) {
  State& s = state();
  std::lock_guard lock(s.mutex);
  return translated(s, english);
}

std::string tr(const std::string& english) {
  return tr(english.c_str());
}

const char* label(const char* english) {
  State& s = state();
  std::lock_guard lock(s.mutex);  // one lock: the cached label is of the language it is for
  auto it = s.labels.find(std::string_view(english));
  if (it == s.labels.end())
    it = s.labels.emplace(english, std::string(translated(s, english)) + "###" + english).first;
  return it->second.c_str();
}

std::string format(const char* pattern, ...) {
  va_list args;
  va_start(args, pattern);
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, pattern, args);
  va_end(args);
  std::string out(n > 0 ? std::size_t(n) : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, pattern, again);
  va_end(again);
  return out;
}

}  // namespace zs::i18n
