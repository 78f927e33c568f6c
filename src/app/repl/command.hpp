#pragma once
// The prompt's language: takes one input line, puts out a command (a formula, or one of
// :load FILE, :save FILE, :set KEY=VALUE, :png FILE, :help, :quit) or a usage error. The
// commands that change or show the surface are carried out by a PromptTarget: the open
// viewer window, or a headless renderer writing PNGs when there is no display.
#include <string>
#include <string_view>
#include <variant>

namespace zs::app {

struct PromptCommand {
  enum class Kind { Formula, Load, Save, Set, Png, Help, Quit, Empty };
  Kind kind = Kind::Empty;
  std::string arg;  // the formula, the file or the KEY=VALUE assignment
};

// Leading and trailing blanks are ignored; a line starting with ':' is a command, anything
// else a formula. Errors come back as text ending in a newline.
std::variant<PromptCommand, std::string> parsePromptLine(std::string_view line);

// The :help text.
std::string promptHelp();

class PromptTarget {
 public:
  virtual ~PromptTarget() = default;
  // Carries out Formula, Load, Save, Set or Png; returns what to print (each line ending in
  // a newline, errors starting with "error:" or holding the caret), "" for nothing.
  virtual std::string run(const PromptCommand& command) = 0;
};

}  // namespace zs::app
