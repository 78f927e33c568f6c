// fork/exec with the three stdio shapes. forkpty gives the child a real terminal, so
// isatty() is true there and libedit prints the prompt and handles the arrow keys.
#include "process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace zs::test {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

[[noreturn]] void execChild(const std::vector<std::string>& argv,
                            const std::vector<EnvChange>& env) {
  for (const EnvChange& e : env) {
    if (e.value.empty())
      unsetenv(e.name.c_str());
    else
      setenv(e.name.c_str(), e.value.c_str(), 1);
  }
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  execv(args[0], args.data());
  _exit(127);
}

}  // namespace

Child::Child(const std::vector<std::string>& argv, const std::vector<EnvChange>& env, Stdio stdio,
             const std::filesystem::path& outputFile) {
  if (stdio == Stdio::Pty) {
    int master = -1;
    pid_ = forkpty(&master, nullptr, nullptr, nullptr);
    if (pid_ == 0) execChild(argv, env);
    inFd_ = outFd_ = master;
  } else if (stdio == Stdio::Pipe) {
    int in[2], out[2];
    if (pipe(in) != 0 || pipe(out) != 0) throw std::runtime_error("pipe failed");
    pid_ = fork();
    if (pid_ == 0) {
      dup2(in[0], 0);
      dup2(out[1], 1);
      dup2(out[1], 2);
      close(in[1]);
      close(out[0]);
      execChild(argv, env);
    }
    close(in[0]);
    close(out[1]);
    inFd_ = in[1];
    outFd_ = out[0];
  } else {
    pid_ = fork();
    if (pid_ == 0) {
      const int fd = open(outputFile.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
      const int null = open("/dev/null", O_RDONLY);
      dup2(null, 0);
      dup2(fd, 1);
      dup2(fd, 2);
      execChild(argv, env);
    }
  }
  if (pid_ < 0) throw std::runtime_error("fork failed");
}

Child::~Child() {
  if (!exited_ && pid_ > 0) {
    kill(pid_, SIGTERM);
    if (wait(5) == -1 && !exited_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  if (inFd_ >= 0) close(inFd_);
  if (outFd_ >= 0 && outFd_ != inFd_) close(outFd_);
}

void Child::write(std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(inFd_, text.data(), text.size());
    if (n <= 0) return;
    text.remove_prefix(std::size_t(n));
  }
}

void Child::closeInput() {
  if (inFd_ >= 0 && inFd_ != outFd_) {
    close(inFd_);
    inFd_ = -1;
  }
}

bool Child::readUntil(std::string_view marker, double seconds, std::size_t from) {
  const auto start = Clock::now();
  for (;;) {
    if (output_.find(marker, std::min(from, output_.size())) != std::string::npos) return true;
    const double left = seconds - since(start);
    if (left <= 0) return false;
    pollfd p{outFd_, POLLIN, 0};
    if (poll(&p, 1, int(left * 1000) + 1) <= 0) continue;
    char buffer[4096];
    const ssize_t n = read(outFd_, buffer, sizeof buffer);
    if (n <= 0) return output_.find(marker, std::min(from, output_.size())) != std::string::npos;
    output_.append(buffer, std::size_t(n));
  }
}

int Child::wait(double seconds) {
  const auto start = Clock::now();
  while (since(start) < seconds) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return -1;
}

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool waitForText(const std::filesystem::path& file, std::string_view marker, double seconds,
                 std::size_t from, std::string* restOfLine) {
  const auto start = Clock::now();
  do {
    const std::string text = readText(file);
    const auto at = from < text.size() ? text.find(marker, from) : std::string::npos;
    if (at != std::string::npos) {
      const auto rest = at + marker.size();
      const auto end = text.find('\n', rest);
      if (end != std::string::npos) {  // only whole lines
        if (restOfLine) *restOfLine = text.substr(rest, end - rest);
        return true;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  } while (since(start) < seconds);
  return false;
}

int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::filesystem::path freshDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("zs-app-test-" + std::to_string(getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace zs::test
