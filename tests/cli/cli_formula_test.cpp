// The command line around a formula that begins with a minus sign (formula_args.hpp), as a
// user meets it; tests/app's ctest entries run the other subcommands with one. The view has
// no display here, so it must get as far as opening the window; a mistake keeps its caret
// under the formula as typed; --help says a formula may begin with a minus sign.
#include <gtest/gtest.h>

#include "process.hpp"

namespace zs::test {
namespace {

struct Result {
  int status;
  std::string output;  // stdout and stderr
};

Result zeroset(const std::vector<std::string>& args, const std::string& name) {
  const auto dir = freshDir("cli-" + name);
  std::vector<std::string> argv{ZS_ZEROSET_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  const auto log = dir / "output.txt";
  Child c(argv, {{"DISPLAY", ""}, {"WAYLAND_DISPLAY", ""}}, Stdio::File, log);
  const int status = c.wait(120);
  return {status, readText(log)};
}

TEST(LeadingMinus, ViewGetsAsFarAsTheWindow) {
  const Result run = zeroset({"view", "-x^2-y^2+z", "--log"}, "view");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find("cannot open a window"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("not expected"), std::string::npos) << run.output;
}

TEST(LeadingMinus, AMistakeKeepsItsCaretUnderTheFormula) {
  const Result run = zeroset({"check", "-x^2 + sinn(y)"}, "check-error");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.output.find("unknown function 'sinn'"), std::string::npos) << run.output;
  // The formula line and the caret line below it: ^^^^ under "sinn", as typed.
  const auto line = run.output.find("-x^2 + sinn(y)");
  ASSERT_NE(line, std::string::npos) << run.output;
  const auto lineStart = run.output.rfind('\n', line) + 1;  // npos + 1 == 0
  const auto caretLine = run.output.find('\n', line) + 1;
  EXPECT_EQ(run.output.find("^^^^", caretLine) - caretLine,
            line - lineStart + std::string("-x^2 + ").size())
      << run.output;
}

TEST(LeadingMinus, HelpSaysSo) {
  for (const char* sub : {"check", "render", "octree", "shader", "bench", "view", "singular"}) {
    const Result run = zeroset({sub, "--help"}, std::string("help-") + sub);
    EXPECT_EQ(run.status, 0) << sub;
    EXPECT_NE(run.output.find("may begin with a minus sign"), std::string::npos) << run.output;
  }
}

}  // namespace
}  // namespace zs::test
