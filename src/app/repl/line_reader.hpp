#pragma once
// Where the prompt's lines come from: takes standard input and puts out one line at a time
// (without its newline) until end of input. On a terminal it prints the prompt and offers
// line editing and history through libedit (kept in ~/.zeroset_history between sessions);
// otherwise it reads plain lines and prints nothing, so scripts can pipe commands in.
#include <memory>
#include <optional>
#include <string>

namespace zs::app {

class LineReader {
 public:
  virtual ~LineReader() = default;
  virtual std::optional<std::string> read(const char* prompt) = 0;
  virtual bool interactive() const = 0;

  // The libedit reader when stdin is a terminal, the plain one otherwise.
  static std::unique_ptr<LineReader> forStdin();
};

}  // namespace zs::app
