// The .po reader against the parts of the format translators and msgmerge write, the
// language choice from locale names and the environment, and the built-in catalogs: each
// parses, names its language, and keeps every printf conversion of its English text.
#include "i18n/po.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <regex>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "i18n/embedded_catalogs.hpp"
#include "i18n/translate.hpp"

namespace zs::i18n {
namespace {

Catalog parsed(const std::string& text) {
  auto r = parsePo(text);
  if (auto* e = std::get_if<PoError>(&r)) ADD_FAILURE() << "line " << e->line << ": " << e->message;
  return std::get<Catalog>(std::move(r));
}

PoError failure(const std::string& text) {
  auto r = parsePo(text);
  EXPECT_TRUE(std::holds_alternative<PoError>(r)) << text;
  return std::holds_alternative<PoError>(r) ? std::get<PoError>(r) : PoError{};
}

TEST(Po, ReadsContinuedStringsEscapesAndTheHeader) {
  const Catalog c = parsed(
      "# translator comment\n"
      "msgid \"\"\n"
      "msgstr \"\"\n"
      "\"Language: es\\n\"\n"
      "\"Content-Type: text/plain; charset=UTF-8\\n\"\n"
      "\n"
      "#: src/app/viewer/panel.cpp\n"
      "#, c-format\n"
      "msgid \"\"\n"
      "\"%d certified \"\n"
      "\"singular points\"\n"
      "msgstr \"%d puntos singulares \"\n"
      "\"certificados\"\n"
      "\n"
      "msgid \"say \\\"hi\\\"\\tand\\\\\\n\"\n"
      "msgstr \"di \\\"hola\\\"\\ty\\\\\\n\"\n");
  EXPECT_EQ(c.language, "es");
  ASSERT_EQ(c.messages.size(), 2u);
  EXPECT_EQ(c.messages.at("%d certified singular points"), "%d puntos singulares certificados");
  EXPECT_EQ(c.messages.at("say \"hi\"\tand\\\n"), "di \"hola\"\ty\\\n");
}

TEST(Po, LeavesOutFuzzyEmptyAndObsoleteMessages) {
  const Catalog c = parsed(
      "msgid \"kept\"\nmsgstr \"guardado\"\n\n"
      "#, fuzzy, c-format\nmsgid \"guessed %d\"\nmsgstr \"adivinado %d\"\n\n"
      "msgid \"not yet\"\nmsgstr \"\"\n\n"
      "#, fuzzy\n#~ msgid \"gone\"\n#~ msgstr \"ido\"\n\n"
      "msgid \"after\"\nmsgstr \"después\"\n");
  EXPECT_EQ(c.messages.size(), 2u);
  EXPECT_EQ(c.messages.count("kept"), 1u);
  EXPECT_EQ(c.messages.count("after"), 1u);
}

TEST(Po, ErrorsNameTheirLine) {
  EXPECT_EQ(failure("msgid \"a\"\nmsgstr \"b\"\nmsgid \"c\"\n").line, 3);  // no msgstr
  EXPECT_EQ(failure("msgid \"a\"\nmsgid \"b\"\nmsgstr \"c\"\n").line, 2);
  EXPECT_EQ(failure("msgid \"a\\q\"\nmsgstr \"b\"\n").line, 1);
  EXPECT_EQ(failure("msgid \"a\nmsgstr \"b\"\n").line, 1);
  EXPECT_EQ(failure("msgid \"a\"\nmsgstr \"b\"\n\"c\" d\n").line, 3);
  EXPECT_EQ(failure("msgstr \"b\"\n").line, 1);
  EXPECT_EQ(failure("msgid \"a\"\nmsgid_plural \"as\"\nmsgstr[0] \"b\"\n").line, 2);
  EXPECT_EQ(failure("msgctxt \"menu\"\nmsgid \"a\"\nmsgstr \"b\"\n").line, 1);
  EXPECT_EQ(failure("hello\n").line, 1);
  EXPECT_EQ(failure("msgid \"a\"\nmsgstr \"b\"\n\nmsgid \"a\"\nmsgstr \"c\"\n").line, 4);
}

TEST(Languages, LocaleNamesPickTheirCatalog) {
  EXPECT_EQ(knownLanguage("es"), "es");
  EXPECT_EQ(knownLanguage("es_ES.UTF-8"), "es");
  EXPECT_EQ(knownLanguage("de-AT"), "de");
  EXPECT_EQ(knownLanguage("DE"), "de");
  EXPECT_EQ(knownLanguage("en_GB"), "en");
  EXPECT_EQ(knownLanguage("fr_FR"), "");
  EXPECT_EQ(knownLanguage("C"), "");
  EXPECT_EQ(knownLanguage(""), "");
}

// Puts the locale variables back as they were, also when a test fails half-way.
struct EnvironmentRestored {
  std::vector<std::pair<const char*, std::optional<std::string>>> saved;
  EnvironmentRestored() {
    for (const char* name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"}) {
      const char* v = std::getenv(name);
      saved.emplace_back(name, v ? std::optional<std::string>(v) : std::nullopt);
    }
  }
  ~EnvironmentRestored() {
    for (const auto& [name, value] : saved) {
      if (value)
        setenv(name, value->c_str(), 1);
      else
        unsetenv(name);
    }
  }
};

// English again after the test, whatever it asserted.
struct LanguageRestored {
  ~LanguageRestored() { setLanguage("en"); }
};

TEST(Languages, TheEnvironmentChoosesAsGettextDoes) {
  const EnvironmentRestored restore;
  auto with = [](const char* language, const char* all, const char* messages, const char* lang) {
    auto put = [](const char* name, const char* v) {
      if (v)
        setenv(name, v, 1);
      else
        unsetenv(name);
    };
    put("LANGUAGE", language);
    put("LC_ALL", all);
    put("LC_MESSAGES", messages);
    put("LANG", lang);
    return languageFromEnvironment();
  };
  EXPECT_EQ(with(nullptr, nullptr, nullptr, nullptr), "en");
  EXPECT_EQ(with(nullptr, nullptr, nullptr, "de_DE.UTF-8"), "de");
  EXPECT_EQ(with(nullptr, nullptr, "es_MX.UTF-8", "de_DE.UTF-8"), "es");
  EXPECT_EQ(with(nullptr, "C.UTF-8", "es_MX.UTF-8", "de_DE.UTF-8"), "en");
  EXPECT_EQ(with("fr:de:es", nullptr, nullptr, "es_ES"), "de");  // the first one known
  EXPECT_EQ(with("fr", nullptr, nullptr, "es_ES"), "es");
  EXPECT_EQ(with("de", nullptr, nullptr, nullptr), "en");  // no locale: "C", LANGUAGE unread
  EXPECT_EQ(with("de", "C.UTF-8", nullptr, "es_ES"), "en");
}

TEST(Languages, TranslationsAndLabelsFollowTheChoice) {
  const LanguageRestored restore;
  ASSERT_TRUE(setLanguage("en"));
  EXPECT_STREQ(tr("gallery"), "gallery");
  EXPECT_STREQ(label("gallery"), "gallery###gallery");
  EXPECT_FALSE(setLanguage("fr"));
  EXPECT_EQ(currentLanguage(), "en");
  for (const Language& l : languages()) {
    if (l.code == "en") continue;
    ASSERT_TRUE(setLanguage(l.code));
    EXPECT_EQ(currentLanguage(), l.code);
    EXPECT_STRNE(tr("gallery"), "gallery") << l.code;
    EXPECT_EQ(std::string(label("gallery")), std::string(tr("gallery")) + "###gallery");
    EXPECT_STREQ(tr("a text no catalog has"), "a text no catalog has");
  }
  EXPECT_EQ(format("%d of %d: %s", 3, 12, "torus"), "3 of 12: torus");
}

// The conversions of a printf pattern, in order ("%.1f ms at %dx%d" -> f d d); "%%" is none.
std::string conversions(const std::string& s) {
  static const std::regex conversion(
      "%[-+ #0]*[0-9*]*(?:\\.[0-9*]+)?(?:hh|h|ll|l|z|j|t|L)?([diouxXeEfgGcsp%])");
  std::string out;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), conversion); it != std::sregex_iterator();
       ++it)
    if ((*it)[1] != "%") out += (*it)[0].str() + " ";
  return out;
}

TEST(Catalogs, EveryOneParsesNamesItsLanguageAndKeepsTheConversions) {
  ASSERT_GE(embeddedCatalogs().size(), 2u);
  for (const EmbeddedCatalog& e : embeddedCatalogs()) {
    auto r = parsePo(e.text);
    ASSERT_TRUE(std::holds_alternative<Catalog>(r))
        << e.code << ".po:" << std::get<PoError>(r).line << ": " << std::get<PoError>(r).message;
    const Catalog& c = std::get<Catalog>(r);
    EXPECT_EQ(c.language, e.code);
    EXPECT_FALSE(e.name.empty());
    for (const auto& [english, translated] : c.messages)
      EXPECT_EQ(conversions(english), conversions(translated)) << e.code << ": " << english;
  }
}

}  // namespace
}  // namespace zs::i18n
