// Mouse and keyboard. ImGui's GLFW backend chains to these callbacks; whatever the panel
// wants (a click on a widget, typing in the formula box) is left to it.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "app/viewer/viewer.hpp"
#include "i18n/translate.hpp"

namespace zs::app {
// The camera motions and key actions are the interact stage's, shared with the web page.
using namespace zs::interact;
namespace {

Viewer* self(GLFWwindow* window) {
  return static_cast<Viewer*>(glfwGetWindowUserPointer(window));
}

}  // namespace

void Viewer::installCallbacks() {
  GLFWwindow* w = window_->window();
  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int mods) {
    Viewer* v = self(win);
    v->noteInput();
    // A shortcut typed into a text box (Ctrl+A) gets a frame of its own, with its modifiers
    // held, and what follows waits for the next: a slow frame may read the whole chord's
    // presses and releases at once, and the box ignores the characters of a frame in which
    // Ctrl is down.
    const bool shortcut = (action == GLFW_PRESS || action == GLFW_REPEAT) &&
                          (mods & (GLFW_MOD_CONTROL | GLFW_MOD_SUPER)) != 0 &&
                          ImGui::GetIO().WantTextInput;
    if (action == GLFW_PRESS && key >= 0 && key < 512 && !shortcut)
      v->pressedSincePoll_.push_back(key);
    if (action == GLFW_PRESS || action == GLFW_REPEAT) {
      // A key pressed after a click that has not reached the panel yet (a slow frame held
      // both) waits for it: the click may take the focus from a text box, which decides
      // whether the key is the viewer's or the box's. So does a key after one that asked for
      // a text box which has not taken the focus yet: it is meant for that box.
      if (v->inputWaits() || shortcut)
        v->waitingKeys_.push_back({key, mods, v->focusPending() || shortcut});
      else
        v->onKey(key, mods);
    }
    self(win)->uiFrames_ = 3;
  });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int) {
    self(win)->noteInput();
    // Where the pointer was at this event: the cursor callbacks come in event order, while
    // glfwGetCursorPos asks the X server where the pointer is now (after later motion).
    if (button >= 0 && button < 3 && (action == GLFW_PRESS || action == GLFW_RELEASE)) {
      Viewer* v = self(win);
      v->mouseButtons_.push_back({button, action == GLFW_PRESS, v->cursorX_, v->cursorY_});
    }
    self(win)->onMouseButton(button, action);
  });
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
    self(win)->noteInput();
    self(win)->onCursor(x, y);
  });
  glfwSetScrollCallback(w, [](GLFWwindow* win, double, double dy) {
    self(win)->noteInput();
    self(win)->onScroll(dy);
  });
  glfwSetCharCallback(w, [](GLFWwindow* win, unsigned) {
    self(win)->noteInput();
    // ImGui's callback, which this one precedes, queues the character for the panel: one
    // typed while input waits is taken back out of that queue (releaseWaitingInput).
    if (self(win)->inputWaits()) ++self(win)->waitingCharsArrived_;
    self(win)->uiFrames_ = 3;
  });
  glfwSetWindowRefreshCallback(w, [](GLFWwindow* win) { self(win)->uiFrames_ = 3; });
  glfwSetFramebufferSizeCallback(w, [](GLFWwindow* win, int, int) { self(win)->dirty_ = true; });
}

void Viewer::holdQuickKeys() {
  ImGuiIO& io = ImGui::GetIO();
  for (int key : pressedSincePoll_) {
    if (!io.KeysDown[key]) {
      io.KeysDown[key] = true;
      heldKeys_.push_back(key);
    }
  }
  pressedSincePoll_.clear();
  if (heldKeys_.empty()) return;
  io.KeyCtrl = io.KeysDown[GLFW_KEY_LEFT_CONTROL] || io.KeysDown[GLFW_KEY_RIGHT_CONTROL];
  io.KeyShift = io.KeysDown[GLFW_KEY_LEFT_SHIFT] || io.KeysDown[GLFW_KEY_RIGHT_SHIFT];
  io.KeyAlt = io.KeysDown[GLFW_KEY_LEFT_ALT] || io.KeysDown[GLFW_KEY_RIGHT_ALT];
  io.KeySuper = io.KeysDown[GLFW_KEY_LEFT_SUPER] || io.KeysDown[GLFW_KEY_RIGHT_SUPER];
}

void Viewer::releaseHeldKeys() {
  if (heldKeys_.empty()) return;
  ImGuiIO& io = ImGui::GetIO();
  GLFWwindow* w = window_->window();
  for (int key : heldKeys_) io.KeysDown[key] = glfwGetKey(w, key) == GLFW_PRESS;
  heldKeys_.clear();
  io.KeyCtrl = io.KeysDown[GLFW_KEY_LEFT_CONTROL] || io.KeysDown[GLFW_KEY_RIGHT_CONTROL];
  io.KeyShift = io.KeysDown[GLFW_KEY_LEFT_SHIFT] || io.KeysDown[GLFW_KEY_RIGHT_SHIFT];
  io.KeyAlt = io.KeysDown[GLFW_KEY_LEFT_ALT] || io.KeysDown[GLFW_KEY_RIGHT_ALT];
  io.KeySuper = io.KeysDown[GLFW_KEY_LEFT_SUPER] || io.KeysDown[GLFW_KEY_RIGHT_SUPER];
}

void Viewer::replayMouseButtons() {
  if (mouseButtons_.empty()) return;
  const MouseButtonEvent e = mouseButtons_.front();
  mouseButtons_.pop_front();
  // A kiosk's idle time counts from when the click acts, not from when it arrived: in slow
  // frames a queue of clicks (taps on the formula keyboard) can take longer to act than the
  // idle time.
  lastInput_ = std::chrono::steady_clock::now();
  buttonsDown_[e.button] = e.pressed;
  ImGuiIO& io = ImGui::GetIO();
  for (int b = 0; b < 3; ++b) io.MouseDown[b] = buttonsDown_[b];
  io.MousePos = ImVec2(float(e.x), float(e.y));
  uiFrames_ = std::max(uiFrames_, 2);  // frames go on until the queue is empty
}

bool Viewer::inputWaits() const {
  return !mouseButtons_.empty() || focusPending() || !waitingKeys_.empty() ||
         !waitingChars_.empty() || waitingCharsArrived_ > 0;
}

void Viewer::releaseWaitingInput() {
  ImGuiIO& io = ImGui::GetIO();
  const int arrived = std::min(waitingCharsArrived_, io.InputQueueCharacters.Size);
  for (int i = io.InputQueueCharacters.Size - arrived; i < io.InputQueueCharacters.Size; ++i)
    waitingChars_.push_back(io.InputQueueCharacters[i]);
  io.InputQueueCharacters.resize(io.InputQueueCharacters.Size - arrived);
  waitingCharsArrived_ = 0;
  // The key that asked for a text box typed its own letter too: not into the box.
  if (focusKey_ >= GLFW_KEY_A && focusKey_ <= GLFW_KEY_Z && !waitingChars_.empty() &&
      std::tolower(int(waitingChars_.front())) == 'a' + (focusKey_ - GLFW_KEY_A)) {
    waitingChars_.erase(waitingChars_.begin());
    focusKey_ = -1;
  }
  // The last click was replayed in the frame before, and the box asked for drew with the
  // focus: the panel's focus is up to date.
  if (!mouseButtons_.empty() || focusPending()) return;
  focusKey_ = -1;
  while (!waitingKeys_.empty()) {
    const KeyEvent e = waitingKeys_.front();
    if (e.forPanel) {
      // The box sees the key as down for one frame (holdQuickKeys lets it go), with its
      // modifiers; one such key a frame, and the characters after the last of them, so that
      // Ctrl+A then a formula selects before it types.
      waitingKeys_.pop_front();
      io.KeysDown[e.key] = true;
      heldKeys_.push_back(e.key);
      io.KeyCtrl = (e.mods & GLFW_MOD_CONTROL) != 0;
      io.KeyShift = (e.mods & GLFW_MOD_SHIFT) != 0;
      io.KeyAlt = (e.mods & GLFW_MOD_ALT) != 0;
      io.KeySuper = (e.mods & GLFW_MOD_SUPER) != 0;
      if (!focusTaken()) onKey(e.key, e.mods);  // the viewer's: the box did not take the focus
      uiFrames_ = std::max(uiFrames_, 2);
      return;
    }
    waitingKeys_.pop_front();
    onKey(e.key, e.mods);
    if (focusPending()) {  // it asked for a text box: what came after it is for that box
      for (KeyEvent& later : waitingKeys_) later.forPanel = true;
      return;
    }
  }
  for (unsigned c : waitingChars_) io.AddInputCharacter(c);
  waitingChars_.clear();
}

void Viewer::onKey(int key, int mods) {
  if (ImGui::GetIO().WantCaptureKeyboard) return;  // typing in the panel
  if (const KeyBinding* binding = findBinding(key, mods)) {
    // A key that puts the cursor in a text box also types its letter, which must not land
    // there (releaseWaitingInput drops it).
    if (binding->action == Action::FocusFormula || binding->action == Action::ToggleGallery)
      focusKey_ = key;
    runAction(binding->action);
  }
}

void Viewer::onMouseButton(int button, int action) {
  uiFrames_ = 3;
  if (action == GLFW_RELEASE && button == dragButton_) {
    dragButton_ = -1;  // the next frame refines to full resolution
    return;
  }
  if (action != GLFW_PRESS || dragButton_ >= 0 || ImGui::GetIO().WantCaptureMouse) return;
  if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) return;
  dragButton_ = button;
  dragX_ = cursorX_;
  dragY_ = cursorY_;
  session_.beginDrag();
}

void Viewer::onCursor(double x, double y) {
  cursorX_ = x;
  cursorY_ = y;
  uiFrames_ = std::max(uiFrames_, 1);
  if (dragButton_ < 0) return;
  int width = 0, height = 0;
  glfwGetWindowSize(window_->window(), &width, &height);
  if (dragButton_ == GLFW_MOUSE_BUTTON_LEFT)
    session_.drag(dragX_, dragY_, x, y, width, height);
  else
    session_.dragLight(dragX_, dragY_, x, y, width, height);
  dirty_ = true;
}

void Viewer::onScroll(double dy) {
  uiFrames_ = 3;
  if (ImGui::GetIO().WantCaptureMouse || dy == 0) return;
  session_.zoom(dy);
  lastWheel_ = std::chrono::steady_clock::now();
  dirty_ = true;
}

void Viewer::showExample(int delta) {
  const int n = int(examples_.size());
  if (n == 0) return;
  showExampleAt(exampleIndex_ < 0 ? (delta > 0 ? 0 : n - 1)
                                  : ((exampleIndex_ + delta) % n + n) % n);
}

void Viewer::toggleGallery() {
  if (gallery_.visible) {
    gallery_.visible = false;
    return;
  }
  openGallery();
}

void Viewer::openGallery() {
  gallery_.visible = true;
  // Described on first use: reading every example's file is not worth it for a viewer that
  // never opens the gallery.
  if (gallery_.entries.size() != examples_.size()) gallery_.entries = describeExamples(examples_);
  gallery_.searchFocus.ask();
  if (options_.log) {
    std::printf("gallery: %zu examples\n", gallery_.entries.size());
    std::fflush(stdout);
  }
}

void Viewer::noteInput() {
  lastInput_ = std::chrono::steady_clock::now();
  inputSinceStart_ = true;
}

void Viewer::returnToStartIfIdle() {
  if (!options_.kiosk || !inputSinceStart_) return;
  // A visitor whose input has not all acted yet, or who waits for a formula they typed, is
  // not idle: the time counts from the later of their last input and the new surface's
  // arrival. (Rebuilds of the same formula, as a playing parameter asks for them all the
  // time, do not hold it back.)
  if (inputWaits() || buildAt_ ||
      (worker_->busy() && session_.scene().formula != session_.preparedScene().formula))
    return;
  const std::chrono::duration<double> idle =
      std::chrono::steady_clock::now() - std::max(lastInput_, lastBuilt_);
  if (idle.count() < options_.kiosk->idleSeconds) return;
  inputSinceStart_ = false;
  // What a visitor left moving stops: a drag, a play button's sweep, a pending build.
  dragButton_ = -1;
  std::fill(panel_.playing.begin(), panel_.playing.end(), 0);
  buildAt_.reset();
  mouseButtons_.clear();
  waitingKeys_.clear();
  waitingChars_.clear();
  std::fill(std::begin(buttonsDown_), std::end(buttonsDown_), false);
  hover_.clear();
  // The exhibit's language for the next visitor.
  if (i18n::currentLanguage() != startLanguage_ && i18n::setLanguage(startLanguage_)) relabel();
  // Only a changed scene is loaded again (a visitor who just passed by leaves it as it was).
  if (session_.scene() != options_.scene || panel_.formula != options_.scene.formula) {
    setScene(options_.scene, startLabel_);
    exampleIndex_ = options_.exampleIndex;
    sceneFile_ = options_.sceneFile;
  }
  gallery_.search.clear();
  panelVisible_ = true;
  if (options_.log) {
    std::printf("idle: back to the start screen\n");
    std::fflush(stdout);
  }
  openGallery();
}

void Viewer::showExampleAt(int index) {
  const int n = int(examples_.size());
  if (index < 0 || index >= n) return;
  exampleIndex_ = index;
  const Example& example = examples_[std::size_t(exampleIndex_)];
  auto loaded = loadExample(example);
  if (auto* err = std::get_if<std::string>(&loaded)) {
    stats_.status = *err;
    return;
  }
  setScene(std::get<Scene>(loaded), exampleLabel(exampleIndex_, n, example.name));
  sceneFile_ = example.file;
  stats_.status.clear();  // the panel shows the example's label
  if (options_.log) {
    std::printf("example %d of %d: %s\n", exampleIndex_ + 1, n, example.name.c_str());
    std::fflush(stdout);
  }
}

void Viewer::relabel() {
  const int n = int(examples_.size());
  if (options_.exampleIndex >= 0 && options_.exampleIndex < n)
    startLabel_ =
        exampleLabel(options_.exampleIndex, n, examples_[std::size_t(options_.exampleIndex)].name);
  if (!stats_.example.empty() && exampleIndex_ >= 0 && exampleIndex_ < n)
    stats_.example = exampleLabel(exampleIndex_, n, examples_[std::size_t(exampleIndex_)].name);
}

void Viewer::runAction(Action action) {
  std::string message;
  if (options_.kiosk && !kioskAllows(action)) {
    const char* refused = N_("not available in this exhibit");
    stats_.status = i18n::tr(refused);
    if (options_.log) {
      std::printf("%s\n", refused);
      std::fflush(stdout);
    }
    return;
  }
  switch (action) {
    case Action::NextExample:
      showExample(1);
      break;
    case Action::PrevExample:
      showExample(-1);
      break;
    case Action::Screenshot:
      waiting_.push_back({{PromptCommand::Kind::Png, {}}, std::nullopt});
      break;
    case Action::WindowShot:
      windowShot_ = true;
      break;
    case Action::SaveScene:
      waiting_.push_back({{PromptCommand::Kind::Save, {}}, std::nullopt});
      break;
    case Action::ExportMesh:
      startMeshExport();
      break;
    case Action::PrintPage:
      startPrint();
      break;
    case Action::FocusFormula:
      panelVisible_ = true;
      panel_.formulaFocus.ask();
      break;
    case Action::TogglePanel:
      panelVisible_ = !panelVisible_;
      break;
    case Action::ToggleGallery:
      toggleGallery();
      break;

    case Action::Quit:
      glfwSetWindowShouldClose(window_->window(), GLFW_TRUE);
      break;
    default: {  // the scene edits and the view's reset are the session's
      const Scene before = session_.scene();
      if (session_.action(action, message) != 0) {
        stats_.status = action == Action::ResetView ? i18n::tr("view reset") : message;
        onSceneEdited(before);
      }
      break;
    }
  }
  if (options_.log && !message.empty()) {
    std::printf("%s\n", message.c_str());
    std::fflush(stdout);
  }
}

}  // namespace zs::app
