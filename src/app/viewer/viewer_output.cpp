// What leaves the viewer: screenshots, saved scenes and the replies to prompt commands.
// All of them wait until no build is queued or running, so they show what was asked for.
#include <GLFW/glfw3.h>
#include <glad/gl.h>

#include <cstdio>
#include <cstring>

#include "app/repl/scene_edit.hpp"
#include "app/viewer/viewer.hpp"
#include "i18n/translate.hpp"
#include "render/image.hpp"

namespace zs::app {

std::future<std::string> Viewer::post(PromptCommand command) {
  std::promise<std::string> reply;
  std::future<std::string> answer = reply.get_future();
  {
    std::lock_guard lock(mutex_);
    if (closed_) {
      reply.set_value("error: the window was closed\n");
      return answer;
    }
    pending_.push_back({std::move(command), std::move(reply)});
  }
  glfwPostEmptyEvent();
  return answer;
}

void Viewer::requestClose() {
  post({PromptCommand::Kind::Quit, {}});
}

void Viewer::runPending() {
  std::deque<Pending> batch;
  {
    std::lock_guard lock(mutex_);
    batch.swap(pending_);
  }
  for (Pending& p : batch) {
    uiFrames_ = 3;
    const PromptCommand& c = p.command;
    switch (c.kind) {
      case PromptCommand::Kind::Formula:
      case PromptCommand::Kind::Set:
      case PromptCommand::Kind::Load: {
        const Scene before = session_.scene();
        if (std::string err = applyPromptEdit(c, session_); !err.empty()) {
          p.reply.set_value(err);
          continue;
        }
        if (c.kind == PromptCommand::Kind::Load) {
          sceneReplaced(c.arg);
          sceneFile_ = c.arg;
          // What SURFER shows differently is worth saying, but the load goes ahead.
          std::fputs(session_.notes().c_str(), stderr);
        } else {
          onSceneEdited(before);
          panel_.formula = session_.scene().formula;
          panel_.formulaError.clear();
          // The window shows the formula at once while its build runs, as when typed.
          if (c.kind == PromptCommand::Kind::Formula) showFirstPicture();
        }
        waiting_.push_back({c, std::move(p.reply)});
        break;
      }
      case PromptCommand::Kind::Save:
      case PromptCommand::Kind::Png:
        waiting_.push_back({c, std::move(p.reply)});
        break;
      case PromptCommand::Kind::Quit:
        glfwSetWindowShouldClose(window_->window(), GLFW_TRUE);
        p.reply.set_value("");
        break;
      case PromptCommand::Kind::Help:
        p.reply.set_value(promptHelp());
        break;
      case PromptCommand::Kind::Empty:
        p.reply.set_value("");
        break;
    }
  }
}

void Viewer::answerWaiting() {
  if (!waiting_.empty() && (worker_->busy() || buildAt_)) {
    // Said once per wait, in the log: an output held for seconds by builds that keep coming.
    const auto now = std::chrono::steady_clock::now();
    if (!waitingSince_) waitingSince_ = now;
    if (options_.log && !waitingSaid_ && now - *waitingSince_ > std::chrono::seconds(2)) {
      waitingSaid_ = true;
      std::printf("%zu outputs wait for the build in progress\n", waiting_.size());
      std::fflush(stdout);
    }
    return;
  }
  waitingSince_.reset();
  waitingSaid_ = false;
  if (waiting_.empty()) return;
  std::vector<Waiting> ready;
  ready.swap(waiting_);
  for (Waiting& w : ready) {
    std::string text = runOutput(w.command);
    if (w.reply) {
      w.reply->set_value(text);
    } else if (!text.empty()) {
      std::fputs(text.c_str(), stdout);  // keys: say where the file went
      std::fflush(stdout);
    }
  }
}

std::string Viewer::runOutput(const PromptCommand& command) {
  switch (command.kind) {
    case PromptCommand::Kind::Png:
      return screenshot(command.arg.empty() ? nextFreePath(options_.outputDir, "zeroset", ".png")
                                            : std::filesystem::path(command.arg));
    case PromptCommand::Kind::Save:
      return save(command.arg.empty() ? nextFreePath(options_.outputDir, "zeroset", ".surf")
                                      : std::filesystem::path(command.arg));
    default:
      // A scene edit: report how its build went (nothing when it is on screen).
      return session_.lastBuildError();
  }
}

std::string Viewer::panelError(std::string_view text) {
  if (text.substr(0, 7) == "error: ") text.remove_prefix(7);
  while (!text.empty() && text.back() == '\n') text.remove_suffix(1);
  return i18n::format(i18n::tr("error: %s"), std::string(text.substr(0, text.find('\n'))).c_str());
}

std::string Viewer::screenshot(const std::filesystem::path& path) {
  int width = 0, height = 0;
  window_->framebufferSize(width, height);
  Frame frame = view_->screenshot(session_.scene().render, session_.scene().domain, width, height);
  std::string text;
  if (!frame.error.empty()) {
    text = "error: " + frame.error + "\n";
  } else if (std::string err = writePng(path.string(), frame.color); !err.empty()) {
    text = "error: " + err + "\n";
  } else {
    text = "screenshot: " + path.string() + "\n";
  }
  stats_.status = text.rfind("error: ", 0) == 0
                      ? panelError(text)
                      : i18n::format(i18n::tr("screenshot: %s"), path.string().c_str());
  return text;
}

void Viewer::captureWindow(int width, int height) {
  windowShot_ = false;
  Image image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
  std::vector<std::uint8_t> rows(image.rgba.size());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  const std::size_t stride = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y)  // GL rows come bottom-up
    std::memcpy(&image.rgba[std::size_t(y) * stride], &rows[std::size_t(height - 1 - y) * stride],
                stride);
  const std::filesystem::path path = nextFreePath(options_.outputDir, "zeroset-window", ".png");
  const std::string err = writePng(path.string(), image);
  stats_.status =
      err.empty() ? i18n::format(i18n::tr("window: %s"), path.string().c_str()) : panelError(err);
  const std::string logged = err.empty() ? "window: " + path.string() : "error: " + err;
  std::printf("%s\n", logged.c_str());
  std::fflush(stdout);
}

std::string Viewer::save(const std::filesystem::path& path) {
  // The image size is the window's, so `zeroset render` of the file gives this picture.
  Scene saved = session_.scene();
  window_->framebufferSize(saved.width, saved.height);
  std::string text = writeSceneFile(path, saved);
  stats_.status =
      text.empty() ? i18n::format(i18n::tr("saved: %s"), path.string().c_str()) : panelError(text);
  if (text.empty()) text = "saved: " + path.string() + "\n";
  return text;
}

}  // namespace zs::app
