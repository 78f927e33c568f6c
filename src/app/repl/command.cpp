// Prompt line parsing. Commands take the rest of the line as one argument, so file names
// with spaces work without quoting.
#include "app/repl/command.hpp"

#include <array>
#include <utility>

namespace zs::app {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

struct CommandSpec {
  std::string_view name;
  PromptCommand::Kind kind;
  const char* argName;  // nullptr: takes no argument
};

constexpr std::array<CommandSpec, 8> kCommands{{
    {"load", PromptCommand::Kind::Load, "FILE"},
    {"save", PromptCommand::Kind::Save, "FILE"},
    {"set", PromptCommand::Kind::Set, "KEY=VALUE"},
    {"png", PromptCommand::Kind::Png, "FILE"},
    {"help", PromptCommand::Kind::Help, nullptr},
    {"quit", PromptCommand::Kind::Quit, nullptr},
    {"q", PromptCommand::Kind::Quit, nullptr},
    {"exit", PromptCommand::Kind::Quit, nullptr},
}};

const CommandSpec* findCommand(std::string_view name) {
  for (const CommandSpec& spec : kCommands)
    if (spec.name == name) return &spec;
  return nullptr;
}

}  // namespace

std::variant<PromptCommand, std::string> parsePromptLine(std::string_view line) {
  line = trim(line);
  if (line.empty()) return PromptCommand{};
  const bool colon = line.front() == ':';
  const std::string_view body = colon ? line.substr(1) : line;
  const auto space = body.find_first_of(" \t");
  const std::string_view name = body.substr(0, space);
  const std::string_view arg = space == std::string_view::npos ? "" : trim(body.substr(space));
  const CommandSpec* spec = findCommand(name);
  if (!colon) {
    // A command word typed without its colon. Alone, a command that takes no argument is
    // that command (as a formula, "help" would be the constant h*e*l*p, which draws
    // nothing); followed by an argument, a command that takes one is pointed at.
    if (spec && !spec->argName && arg.empty()) return PromptCommand{spec->kind, ""};
    if (spec && spec->argName && !arg.empty()) {
      return "error: '" + std::string(name) + "' is a command: did you mean :" + std::string(name) +
             " " + std::string(arg) + "?\n";
    }
    return PromptCommand{PromptCommand::Kind::Formula, std::string(line)};
  }
  if (!spec) {
    return "error: unknown command ':" + std::string(name) + "'\nhint: :help lists the commands\n";
  }
  if (spec->argName && arg.empty())
    return "error: :" + std::string(name) + " needs " + spec->argName + "\n";
  if (!spec->argName && !arg.empty())
    return "error: :" + std::string(name) + " takes no argument\n";
  return PromptCommand{spec->kind, std::string(arg)};
}

std::string promptHelp() {
  return "Type a formula F(x,y,z) (e.g. x^2 + y^2 - z^2 - 0.3) to show its zero set, or:\n"
         "  :load FILE       load a .surf scene or a SURFER .jsurf file\n"
         "  :save FILE       save the current scene (formula, parameters, camera, lights,\n"
         "                   every setting) as a .surf\n"
         "  :set KEY=VALUE   change one scene key, e.g. :set tracing.epsilon=0.01,\n"
         "                   :set params.a=0.5, :set camera.eye=[0,1,4]\n"
         "  :png FILE        render the current scene to a PNG\n"
         "  :help            this text\n"
         "  :quit            leave (so do quit, exit and Ctrl+D)\n";
}

}  // namespace zs::app
