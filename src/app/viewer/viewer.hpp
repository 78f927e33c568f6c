#pragma once
// The interactive viewer (`zeroset view`, and the window behind the prompt): takes a Scene
// and options, opens a GLFW window with a Dear ImGui panel, and runs until it is closed.
// Puts out frames, plus screenshots (PNG) and saved views (.surf) in the output folder,
// each path printed on stdout as "screenshot: PATH" / "saved: PATH". The scene, what each
// edit rebuilds, rollback and first-picture sizing are the session's (session/session.hpp):
// the viewer holds one and wires the window's input, the panel and GL to it. Surfaces are
// built on the session's worker thread (session/surface_worker.hpp); only the GL upload
// runs on the main thread. Another thread (the prompt) may post commands; they run on the
// main thread between frames.
#include <array>
#include <chrono>
#include <deque>
#include <filesystem>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/repl/command.hpp"
#include "app/shader_warmer.hpp"
#include "app/viewer/examples.hpp"
#include "app/viewer/gallery_panel.hpp"
#include "app/viewer/hover_probe.hpp"
#include "app/viewer/panel.hpp"
#include "app/viewer/surface_view.hpp"
#include "interact/key_bindings.hpp"
#include "interact/kiosk.hpp"
#include "interact/trace_budget.hpp"
#include "render/glfw_context.hpp"
#include "session/session.hpp"
#include "session/surface_worker.hpp"

namespace zs::app {

struct ViewerOptions {
  Scene scene;
  std::string title = "zeroset";
  std::filesystem::path outputDir = ".";  // screenshots and saved scenes
  std::filesystem::path sceneFile;        // the scene's file, if any: meshes are written beside it
  int exampleIndex = -1;  // the scene is this entry of listExamples() (N/P go on from it)
  int dragScale = 0;      // fixed resolution divisor while dragging; 0 = adapt to hold ~30 fps
  // Print events on stdout: "ready WxH" once the first surface is on screen at full
  // resolution, "built FORMULA", and each key action's message (scripts and tests).
  bool log = false;
  // An exhibit (docs/viewer.md, "Kiosk mode"): fullscreen; the gallery over `scene` is the
  // start screen, and the viewer goes back to it after the policy's idle time; no quitting
  // and no files written; typed formulas within the degree limit; the formula keyboard.
  std::optional<interact::KioskPolicy> kiosk;
};

class Viewer {
 public:
  // Opens the window (hidden until the first frame) and starts the first build. Fails with
  // a message when there is no display or no GL 3.3 context; never aborts.
  static std::unique_ptr<Viewer> open(const ViewerOptions& options, std::string& error);
  ~Viewer();

  // Runs the event loop until the window is closed, Ctrl+Q, or requestClose().
  void run();

  // Thread-safe. Queues a prompt command; the future holds what to print once it has been
  // carried out (a formula: once it is on screen or failed to build). After the window
  // closed, commands are answered with an error at once.
  std::future<std::string> post(PromptCommand command);
  void requestClose();

 private:
  explicit Viewer(const ViewerOptions& options);
  struct Pending {
    PromptCommand command;
    std::promise<std::string> reply;
  };
  // A command that runs once no build is queued or running, so it sees the surface that
  // was asked for: a screenshot, a save, or the reply to a formula. Keys have no reply.
  struct Waiting {
    PromptCommand command;
    std::optional<std::promise<std::string>> reply;
  };

  // viewer.cpp: the loop and its pieces
  void frame();
  void traceIfNeeded(int width, int height);
  bool interacting() const;
  int reducedScale(int width, int height) const;

  // viewer_build.cpp: scene edits and builds
  void takeBuild();
  // Hands the session's build request, if its scene needs one, to the worker.
  void requestBuild();
  // After an edit the session took (`before`: the scene before it): a new parameter value
  // shown at once, the build the session asks for, a redraw.
  void onSceneEdited(const Scene& before);
  void applyTypedFormula();
  // The typed formula's first picture by the tape interpreter, while its build runs.
  void showFirstPicture();
  // A whole new scene: into the session, then what a new scene resets in the window.
  void setScene(const Scene& scene, const std::string& exampleName);
  void sceneReplaced(const std::string& exampleName);

  // viewer_input.cpp: GLFW callbacks and key actions
  void installCallbacks();
  void onKey(int key, int mods);
  // Dear ImGui (1.86) reads each key as held or not at the start of a frame, so a key pressed
  // and released within one event poll (a slow frame: a first picture, a big trace) would
  // never reach the panel: Enter and Ctrl+A in the formula box were lost. Such keys are held
  // down for one frame.
  void holdQuickKeys();    // after polling events
  void releaseHeldKeys();  // before the next poll
  // The same for mouse buttons: two taps within one poll (a formula keyboard under a quick
  // finger) would reach ImGui as one click, at the second tap's place. Each press and
  // release is handed to ImGui in a frame of its own, where it happened.
  void replayMouseButtons();  // after ImGui's NewFrame of the platform backend
  // Input that waits: for clicks before it to reach the panel, or for a text box asked for
  // before it to take the focus; released at the start of a frame once they have.
  void releaseWaitingInput();
  bool inputWaits() const;
  void onMouseButton(int button, int action);
  void onCursor(double x, double y);
  void onScroll(double dy);
  void runAction(interact::Action action);
  void showExample(int delta);
  void showExampleAt(int index);
  void toggleGallery();
  void openGallery();
  // Kiosk mode: any input restarts the idle time; once it runs out, the start screen.
  void noteInput();
  void returnToStartIfIdle();

  // viewer_output.cpp: screenshots, saves and prompt commands
  void runPending();
  void answerWaiting();
  std::string runOutput(const PromptCommand& command);
  std::string screenshot(const std::filesystem::path& path);
  std::string save(const std::filesystem::path& path);
  void captureWindow(int width, int height);  // the back buffer, panel included

  // viewer_mesh.cpp: "Export mesh" runs on its own thread; the frame loop collects it
  void startMeshExport();
  void finishMeshExport();
  // viewer_print.cpp: "Print page" the same way
  void startPrint();
  void finishPrint();
  // A finished file job (mesh, print): its message in the status line and on stdout.
  // What a finished export or print says: the whole text for stdout (English, as the CLI's)
  // and one line for the panel, in the viewer's language.
  struct FileJobResult {
    std::string log;
    std::string status;
  };
  // An error text as the panel shows it: "error: ..." in the viewer's language, once, on one
  // line (the CLI's texts it wraps already start with "error: " and end with a newline).
  static std::string panelError(std::string_view text);
  void finishFileJob(std::future<FileJobResult>& job);
  // The example labels again, in the language just picked.
  void relabel();

  ViewerOptions options_;
  std::unique_ptr<GlfwWindowContext> window_;
  std::unique_ptr<SurfaceView> view_;
  std::shared_ptr<ShaderWarmer> warmer_;  // the worker's second job (shader_warmer.hpp)
  std::unique_ptr<session::SurfaceWorker> worker_;
  bool imguiReady_ = false;

  session::Session session_;      // the scene edited and shown, and the surface on screen
  std::size_t builtProgram_ = 0;  // its program (ShaderWarmer::programKey)
  std::vector<Example> examples_;
  int exampleIndex_ = -1;
  PanelState panel_;
  PanelStats stats_;
  bool panelVisible_ = true;
  GalleryPanel gallery_;
  HoverProbe hover_;  // the readout under the pointer

  // Tracing state: `dirty_` = the scene changed since the last trace; `refine_` = the image
  // on screen is a reduced-resolution one.
  bool dirty_ = true, refine_ = false;
  int uiFrames_ = 3;  // frames still to draw for ImGui to settle after an event
  std::optional<std::chrono::steady_clock::time_point> buildAt_;  // debounced formula build
  std::string quickFormula_;        // the formula of the first picture on screen, "" if none
  bool interpretersAsked_ = false;  // the worker was asked to warm the interpreters
  std::array<bool, 2> firstPicturesSaid_{};       // [sampling]: "first pictures ready" was logged
  std::vector<int> pressedSincePoll_, heldKeys_;  // holdQuickKeys
  struct MouseButtonEvent {
    int button;
    bool pressed;
    double x, y;
  };
  std::deque<MouseButtonEvent> mouseButtons_;  // replayMouseButtons
  struct KeyEvent {
    int key, mods;
    bool forPanel;  // came while a text box was about to take the focus: ImGui gets it too
  };
  // Input that came after a click not yet replayed, or after a key that asked for the
  // formula or search box before the box has the focus (releaseWaitingInput): the keys, and
  // the characters taken back out of ImGui's queue (counted as they arrive, taken at the
  // frame's start).
  std::deque<KeyEvent> waitingKeys_;
  // The key that last asked for the formula or search box (GLFW key code, -1 none): its own
  // character is dropped, not typed into that box.
  int focusKey_ = -1;
  bool focusPending() const {
    return panel_.formulaFocus.pending() || gallery_.searchFocus.pending();
  }
  bool focusTaken() const { return panel_.formulaFocus.taken() || gallery_.searchFocus.taken(); }
  std::vector<unsigned> waitingChars_;
  int waitingCharsArrived_ = 0;
  bool buttonsDown_[3] = {false, false, false};  // as ImGui was last told
  std::chrono::steady_clock::time_point lastWheel_{};
  double msPerPixel_ = 0;  // from the latest trace, to pick the reduced scale
  bool sliderActive_ = false, readyPrinted_ = false;

  // Mouse drags: which button and where it started (the session keeps the camera and the
  // light at the start).
  int dragButton_ = -1;
  double dragX_ = 0, dragY_ = 0, cursorX_ = 0, cursorY_ = 0;

  // Frame timing for the panel.
  std::chrono::steady_clock::time_point fpsStart_ = std::chrono::steady_clock::now();
  int fpsFrames_ = 0;
  double fps_ = 0;
  // Trace counts and total milliseconds at full [0] and reduced [1] resolution, for the
  // summary --log prints at exit.
  int traces_[2] = {0, 0};
  double traceMsTotal_[2] = {0, 0};
  int lastScale_ = 1;
  bool uncounted_ = false;  // the next trace compiles the new shader (JIT): not counted

  std::mutex mutex_;  // guards pending_ and closed_
  std::deque<Pending> pending_;
  bool closed_ = false;
  std::vector<Waiting> waiting_;  // main thread only
  // Since when waiting_ has waited for builds, and whether the log has said so.
  std::optional<std::chrono::steady_clock::time_point> waitingSince_;
  bool waitingSaid_ = false;
  bool windowShot_ = false;          // Shift+C: capture before the next swap
  std::filesystem::path sceneFile_;  // where the shown scene was loaded from, if anywhere
  std::string startLabel_;           // the start scene's example label, if it is one
  std::string startLanguage_;        // a kiosk's, restored for the next visitor
  std::chrono::steady_clock::time_point lastInput_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point lastBuilt_ = lastInput_;  // a new formula's build arrived
  bool inputSinceStart_ = false;           // kiosk: the start screen was left
  std::future<FileJobResult> meshExport_;  // a running export's summary
  std::future<FileJobResult> print_;       // a running print's message
};

}  // namespace zs::app
