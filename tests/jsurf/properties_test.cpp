// Java .properties reading: separators, comments, continued lines, escapes, and the place
// of every value byte in the file.
#include "jsurf/properties.hpp"

#include <gtest/gtest.h>

namespace zs::jsurf {
namespace {

TEST(Properties, SeparatorsCommentsAndBlankLines) {
  const auto p = readProperties("# comment\n! also a comment\n\n a = 1\nb:2\nc 3\nd\n  e=\n");
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0].key, "a");
  EXPECT_EQ(p[0].value, "1");
  EXPECT_EQ(p[1].key, "b");
  EXPECT_EQ(p[1].value, "2");
  EXPECT_EQ(p[2].key, "c");
  EXPECT_EQ(p[2].value, "3");
  EXPECT_EQ(p[3].key, "d");
  EXPECT_EQ(p[3].value, "");
  EXPECT_EQ(p[4].key, "e");
  EXPECT_EQ(p[4].keyPos.line, 8);
  EXPECT_EQ(p[4].keyPos.column, 3);
}

TEST(Properties, ContinuedLinesDropTheirLeadingBlanksAndKeepPositions) {
  const auto p = readProperties("f=x^2 + \\\n      y^2\r\ng=1\\\\\nh=2");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].value, "x^2 + y^2");
  // 'y' is on line 2, column 7.
  const std::size_t y = p[0].value.find('y');
  EXPECT_EQ(p[0].valuePos[y].line, 2);
  EXPECT_EQ(p[0].valuePos[y].column, 7);
  EXPECT_EQ(p[1].value, "1\\");  // an even number of backslashes does not continue
  EXPECT_EQ(p[2].key, "h");
  EXPECT_EQ(p[2].keyPos.line, 4);
}

TEST(Properties, EscapesAreDecoded) {
  const auto p = readProperties("k\\ ey=a\\=b\\tc\\u0041\\u00e9\n");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].key, "k ey");
  EXPECT_EQ(p[0].value, "a=b\tcA\xC3\xA9");
  EXPECT_EQ(p[0].valuePos.size(), p[0].value.size() + 1);
}

TEST(Properties, EscapingReadsBack) {
  for (const std::string text : {" lead", "a=b:c#d!e", "back\\slash", "tab\tnew\nline", ""}) {
    const std::string file = escapeProperty("my key", true) + "=" + escapeProperty(text) + "\n";
    const auto p = readProperties(file);
    ASSERT_EQ(p.size(), 1u) << file;
    EXPECT_EQ(p[0].key, "my key");
    EXPECT_EQ(p[0].value, text) << file;
  }
}

TEST(Properties, AnyBytesAreReadWithoutFailing) {
  const std::string junk("\\\\\\\n=\0\x80\xff:\\u12\\", 16);
  const auto p = readProperties(junk);
  for (const Property& prop : p) EXPECT_EQ(prop.valuePos.size(), prop.value.size() + 1);
}

}  // namespace
}  // namespace zs::jsurf
