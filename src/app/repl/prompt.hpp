#pragma once
// `zeroset` with no arguments: the formula prompt. Takes lines from standard input
// (line_reader.hpp) and carries each out on the viewer window when a display is available,
// or on the headless PNG renderer when not (no DISPLAY / WAYLAND_DISPLAY, or the window
// cannot open). Prints "F(x,y,z) = " before each line on a terminal; errors print with
// their caret and the prompt goes on. Returns the process exit code.
namespace zs::app {

int runPrompt();

}  // namespace zs::app
