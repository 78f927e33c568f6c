#pragma once
// The language of the viewer's and the web page's texts. English is written in the code, and
// every other language comes from a gettext catalog (po/<code>.po) built into the program,
// so nothing is looked up on disk and the web build carries the same catalogs. The CLI stays
// English. docs/languages.md explains how texts are marked and translations kept complete.
//
// Marking: tr("text") where a text is shown, label("text") for an ImGui widget whose label is
// also its identity (the English text stays the ID, so switching languages keeps the widget's
// state), N_("text") where a text sits in a table and is translated where it is shown.
#include <span>
#include <string>
#include <string_view>

#define N_(text) text

namespace zs::i18n {

struct Language {
  std::string_view code;  // ISO 639-1: "en", "es", "de"
  std::string_view name;  // in its own language: "English", "Español", "Deutsch"
};

// English first, then every built-in catalog.
std::span<const Language> languages();

// The language the environment asks for, as gettext reads it: the first known language of
// LANGUAGE's list, unless the locale (LC_ALL, else LC_MESSAGES, else LANG) is "C"; else the
// locale's own ("de_AT.UTF-8" is "de"); "en" otherwise.
std::string languageFromEnvironment();

// "es", "es_ES", "es-ES.UTF-8" and "ES" all name Spanish; "" when no catalog matches.
std::string knownLanguage(std::string_view tag);

// False, and no change, for a language without a catalog.
bool setLanguage(std::string_view tag);
std::string_view currentLanguage();

// The translation of `english` in the current language, or `english` itself. The pointer
// stays valid for the program's life.
// format_arg: the compiler checks printf-style uses against the English pattern.
const char* tr(const char* english) __attribute__((format_arg(1)));
std::string tr(const std::string& english);

// tr(english) + "###" + english: ImGui shows the translation and keys the widget on the
// English text. Valid until the language changes.
const char* label(const char* english);

// printf-style formatting of a translated pattern, for messages with numbers in them.
std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

}  // namespace zs::i18n
