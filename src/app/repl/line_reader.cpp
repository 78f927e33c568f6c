// libedit through its readline-compatible API (BSD licensed, unlike GNU readline).
#include "app/repl/line_reader.hpp"

#include <editline/readline.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace zs::app {
namespace {

class PlainReader final : public LineReader {
 public:
  std::optional<std::string> read(const char*) override {
    std::string line;
    if (!std::getline(std::cin, line)) return std::nullopt;
    return line;
  }
  bool interactive() const override { return false; }
};

class EditReader final : public LineReader {
 public:
  EditReader() {
    using_history();
    stifle_history(1000);
    if (const char* home = std::getenv("HOME"); home && *home) {
      historyFile_ = std::string(home) + "/.zeroset_history";
      read_history(historyFile_.c_str());  // a missing file is fine: the first run
    }
  }

  std::optional<std::string> read(const char* prompt) override {
    char* raw = readline(prompt);
    if (!raw) return std::nullopt;  // Ctrl+D on an empty line
    std::string line(raw);
    std::free(raw);
    // Only lines worth recalling: not blank, not a repeat of the previous one.
    if (line.find_first_not_of(" \t") != std::string::npos && line != last_) {
      add_history(line.c_str());
      last_ = line;
      if (!historyFile_.empty()) write_history(historyFile_.c_str());
    }
    return line;
  }
  bool interactive() const override { return true; }

 private:
  std::string historyFile_;
  std::string last_;
};

}  // namespace

std::unique_ptr<LineReader> LineReader::forStdin() {
  if (isatty(STDIN_FILENO)) return std::make_unique<EditReader>();
  return std::make_unique<PlainReader>();
}

}  // namespace zs::app
