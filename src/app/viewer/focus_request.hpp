// A text box asked to take the keyboard focus (F for the formula box, G for the gallery's
// search). ImGui moves the focus to the box a frame after SetKeyboardFocusHere, and the
// viewer learns that the box has it only the frame after that: until the box is seen
// active, keys typed are meant for it and wait (Viewer::releaseWaitingInput).
#pragma once

#include <imgui.h>

namespace zs::app {

class FocusRequest {
 public:
  void ask() {
    asked_ = true;
    taken_ = false;
  }
  bool pending() const { return asked_ || framesLeft_ > 0; }
  // Whether the box took the focus at the last request (keys then are the box's alone).
  bool taken() const { return taken_; }

  // Right before the box's widget.
  void beforeItem() {
    drawn_ = true;
    if (!asked_) return;
    ImGui::SetKeyboardFocusHere();
    asked_ = false;
    framesLeft_ = kFramesToWait;
  }
  // Right after it.
  void afterItem() {
    if (framesLeft_ == 0) return;
    if (ImGui::IsItemActive()) {
      taken_ = true;
      framesLeft_ = 0;
    } else {
      --framesLeft_;
    }
  }
  // After the frame's UI: where it did not draw the box (a collapsed window), the request
  // lapses rather than holding the keys for good.
  void endFrame() {
    if (!drawn_) {
      asked_ = false;
      framesLeft_ = 0;
    }
    drawn_ = false;
  }

 private:
  // ImGui needs one; more only where the box cannot take the focus at all.
  static constexpr int kFramesToWait = 3;
  bool asked_ = false;
  int framesLeft_ = 0;
  bool taken_ = false;
  bool drawn_ = false;
};

}  // namespace zs::app
