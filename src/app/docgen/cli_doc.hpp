#pragma once
// zeroset-docgen: takes the CLI11 tree that main() parses with (app/cli.hpp) and puts out
// the man page and the bash and zsh completion scripts, so all three say what --help says.
// The tree is first read into the plain description below; each writer works from it.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace zs::docgen {

struct OptionDoc {
  std::vector<std::string> names;    // "-o", "--output"; for a positional its name: "input"
  std::string value;                 // "TEXT", "INT", ...; empty for a flag
  std::vector<std::string> choices;  // from CLI::IsMember: "egl", "osmesa"
  std::string constraint;            // any other validator's text: "INT in [0 - 20]"
  int count = 1;                     // values per use (--domain takes 6)
  std::string description;
  bool positional = false;
  bool required = false;
};

struct CommandDoc {
  std::string name;  // empty for the top level
  std::string description;
  std::string footer;
  std::vector<OptionDoc> options;  // positionals last
};

struct CliDoc {
  CommandDoc top;
  std::vector<CommandDoc> commands;
};

CliDoc describe(CLI::App& app);

// The long name of an option ("--output"), else its first.
std::string primaryName(const OptionDoc& option);

// The page, with `sections` (roff) split at the line `.\" @COMMANDS@`: the part before goes
// after SYNOPSIS, the part after at the end. Empty on a malformed `sections`.
std::string manPage(const CliDoc& doc, const std::string& version, const std::string& sections);

// Completion scripts. `sceneKeys` are the dotted keys --set completes (KEY=).
std::string bashCompletion(const CliDoc& doc, const std::vector<std::string>& sceneKeys);
std::string zshCompletion(const CliDoc& doc, const std::vector<std::string>& sceneKeys);

// How a value is completed: a file, a folder, a scene key, a .surf file (INPUT), or nothing
// in particular. The
// type of an option does not tell files from folders, so the options that name one are
// listed here, next to the writers that use them.
enum class ValueKind { None, File, Directory, SceneKey, SceneFile };
ValueKind valueKind(const OptionDoc& option);

}  // namespace zs::docgen
