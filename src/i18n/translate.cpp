#include "i18n/translate.hpp"

#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <stdexcept>
#include <unordered_map>
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
        throw std::logic_error("po/" + std::string(e.code) + ".po:" +
                               std::to_string(error->line) + ": " + error->message);
      l.catalogs.emplace(std::string(e.code), std::move(std::get<Catalog>(parsed)));
      l.languages.push_back({e.code, e.name});
    }
    return l;
  }();
  return all;
}

struct State {
  std::mutex mutex;
  std::string code = "en";
  const Catalog* catalog = nullptr;
  std::unordered_map<std::string, std::string> labels;  // of the current language
};

State& state() {
  static State s;
  return s;
}

}  // namespace

std::span<const Language> languages() { return loaded().languages; }

std::string knownLanguage(std::string_view tag) {
  std::string code;
  for (char c : tag) {
    if (c == '_' || c == '-' || c == '.' || c == '@') break;
    code += char(std::tolower(static_cast<unsigned char>(c)));
  }
  for (const Language& l : languages())
    if (l.code == code) return code;
  return {};
}

std::string languageFromEnvironment() {
  // LANGUAGE is a priority list ("de:en"); the others name one locale each. "C" and
  // "POSIX" are English.
  if (const char* list = std::getenv("LANGUAGE"); list && *list) {
    std::string_view rest(list);
    while (!rest.empty()) {
      const std::size_t colon = rest.find(':');
      const std::string code = knownLanguage(rest.substr(0, colon));
      if (!code.empty()) return code;
      if (colon == std::string_view::npos) break;
      rest.remove_prefix(colon + 1);
    }
  }
  for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"})
    if (const char* v = std::getenv(name); v && *v) {
      const std::string code = knownLanguage(v);
      return code.empty() ? "en" : code;
    }
  return "en";
}

bool setLanguage(std::string_view tag) {
  const std::string code = knownLanguage(tag);
  if (code.empty()) return false;
  State& s = state();
  std::lock_guard lock(s.mutex);
  if (s.code == code) return true;
  s.code = code;
  const auto& catalogs = loaded().catalogs;
  const auto it = catalogs.find(code);
  s.catalog = it == catalogs.end() ? nullptr : &it->second;
  s.labels.clear();
  return true;
}

std::string_view currentLanguage() {
  State& s = state();
  std::lock_guard lock(s.mutex);
  return s.code;
}

const char* tr(const char* english) {
  State& s = state();
  std::lock_guard lock(s.mutex);
  if (!s.catalog) return english;
  const auto it = s.catalog->messages.find(english);
  return it == s.catalog->messages.end() ? english : it->second.c_str();
}

std::string tr(const std::string& english) { return tr(english.c_str()); }

const char* label(const char* english) {
  const char* shown = tr(english);
  State& s = state();
  std::lock_guard lock(s.mutex);
  auto [it, inserted] = s.labels.try_emplace(english);
  if (inserted) it->second = std::string(shown) + "###" + english;
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
