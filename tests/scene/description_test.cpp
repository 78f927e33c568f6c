// The description comment at the top of a .surf file, and its one-line summary.
#include "scene/description.hpp"

#include <gtest/gtest.h>

namespace zs {
namespace {

TEST(SceneDescription, LeadingCommentBlockAsOneParagraph) {
  EXPECT_EQ(sceneDescription(
                "\n# The Barth sextic, degree 6.\n#   Icosahedral.\n#\nformula = \"x\"\n# late"),
            "The Barth sextic, degree 6. Icosahedral.");
  EXPECT_EQ(sceneDescription("## Title ##\r\nformula = \"x\""), "Title ##");
}

TEST(SceneDescription, NoneWhenTheFileDoesNotOpenWithAComment) {
  EXPECT_EQ(sceneDescription("formula = \"x\"\n# a comment after the first key\n"), "");
  EXPECT_EQ(sceneDescription(""), "");
  EXPECT_EQ(sceneDescription("#\n#\n"), "");
}

TEST(SceneDescription, SummaryIsTheGalleryLineWhenThereIsOne) {
  // examples/README.md's form: NAME, an em dash, the degree, a colon, one line.
  EXPECT_EQ(
      summaryLine("# Barth sextic \u2014 degree 6, 65 nodes: the most a sextic can have. Really.\n"
                  "# More.\nformula = \"x\"\n"),
      "Barth sextic \u2014 degree 6, 65 nodes: the most a sextic can have. Really.");
}

TEST(SceneDescription, SummaryIsTheFirstSentenceOtherwise) {
  EXPECT_EQ(summaryLine("# Thesis, Table 5.1, surface 1: a paraboloid.\n# Degree 2.\n"),
            "Thesis, Table 5.1, surface 1: a paraboloid.");
  EXPECT_EQ(summaryLine("# No full stop at all\n"), "No full stop at all");
  EXPECT_EQ(summaryLine("formula = \"x\" # not a description\n"), "");
}

TEST(SceneDescription, ShortenedAtAWord) {
  const std::string s = shortened("aaaa bbbb cccc dddd eeee ffff", 16);
  EXPECT_EQ(s, "aaaa bbbb...");
  EXPECT_LE(s.size(), 16u);
  // Code points, not bytes: twenty e-acutes fit in 20.
  std::string accents;
  for (int i = 0; i < 20; ++i) accents += "\xC3\xA9";
  EXPECT_EQ(shortened(accents, 20), accents);
}

}  // namespace
}  // namespace zs
