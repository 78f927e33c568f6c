#pragma once
// Child processes for the app tests: takes an argv and environment changes, puts out a
// running `zeroset` whose stdout (and stderr) goes to a file, a pipe, or a pseudo-terminal,
// with helpers that wait for text to appear (every wait has a deadline, so a hung viewer
// fails the test instead of hanging ctest).
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace zs::test {

struct EnvChange {
  std::string name;
  std::string value;  // an empty value unsets the variable
};

enum class Stdio {
  File,  // stdout + stderr appended to `outputFile`; stdin from /dev/null
  Pipe,  // stdin from inFd (the test writes), stdout + stderr to outFd (the test reads)
  Pty,   // all three on a new pseudo-terminal; the test reads and writes masterFd
};

class Child {
 public:
  Child(const std::vector<std::string>& argv, const std::vector<EnvChange>& env, Stdio stdio,
        const std::filesystem::path& outputFile = {});
  ~Child();  // kills (SIGTERM, then SIGKILL) if still running
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  pid_t pid() const { return pid_; }
  void write(std::string_view text);  // to stdin (Pipe) or the terminal (Pty)
  void closeInput();                  // end of input (Pipe)
  // Reads (Pipe/Pty) until `marker` appears after `from` in everything read so far, or the
  // deadline; returns whether it appeared. output() holds all text read.
  bool readUntil(std::string_view marker, double seconds, std::size_t from = 0);
  const std::string& output() const { return output_; }
  // Waits for exit; the exit status, or -1 on timeout / signal.
  int wait(double seconds);

 private:
  pid_t pid_ = -1;
  int inFd_ = -1, outFd_ = -1;
  std::string output_;
  bool exited_ = false;
};

// The file's text (empty when missing).
std::string readText(const std::filesystem::path& path);

// Polls a log file until a line containing `marker` appears after `from` bytes; returns
// the rest of that line after the marker, or nothing on timeout.
bool waitForText(const std::filesystem::path& file, std::string_view marker, double seconds,
                 std::size_t from, std::string* restOfLine = nullptr);

// Runs a shell command (xdotool, ...) and returns its exit status.
int shell(const std::string& command);

// A fresh empty folder under the system temp folder, named after the current test.
std::filesystem::path freshDir(const std::string& name);

}  // namespace zs::test
