// The viewer's loop. Each window frame: run posted commands, take a finished build and
// upload it, draw the panel (which edits the scene), trace only if something changed
// (reduced resolution while the user drags, full resolution once idle), blit, draw the
// panel on top, swap. With nothing to do it sleeps in glfwWaitEvents, so an idle viewer
// costs no CPU; the worker and the prompt wake it with glfwPostEmptyEvent.
#include "app/viewer/viewer.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>

#include "app/viewer/fonts.hpp"
#include "app/viewer/formula_keyboard.hpp"
#include "i18n/translate.hpp"
#include "interact/trace_budget.hpp"
#include "pipeline/quick_surface.hpp"

namespace zs::app {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

Viewer::Viewer(const ViewerOptions& options) : options_(options) {}

std::unique_ptr<Viewer> Viewer::open(const ViewerOptions& options, std::string& error) {
  std::unique_ptr<Viewer> v(new Viewer(options));
  const int w = std::clamp(options.scene.width, 200, 4096);
  const int h = std::clamp(options.scene.height, 200, 4096);
  auto created = GlfwWindowContext::create(w, h, options.title, true);
  if (!created.context) {
    error = created.error;
    return nullptr;
  }
  v->window_ = std::move(created.context);
  glfwSetWindowUserPointer(v->window_->window(), v.get());
  if (options.kiosk) {
    // The whole primary screen, and a close request (a window manager's, Alt+F4) ignored:
    // the exhibit's operator ends it with a signal.
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
      if (const GLFWvidmode* mode = glfwGetVideoMode(monitor))
        glfwSetWindowMonitor(v->window_->window(), monitor, 0, 0, mode->width, mode->height,
                             mode->refreshRate);
    }
    glfwSetWindowCloseCallback(v->window_->window(),
                               [](GLFWwindow* w) { glfwSetWindowShouldClose(w, GLFW_FALSE); });
  }
  glfwSwapInterval(0);  // llvmpipe frames are slow enough; vsync would only add latency
  v->view_ = std::make_unique<SurfaceView>();
  // First pictures in a hidden window's context of their own (SurfaceView says why); where
  // none can be made they share the window's.
  auto first = GlfwWindowContext::create(16, 16, options.title, false);
  v->window_->makeCurrent();  // a made context is current
  if (first.context) v->view_->drawFirstPicturesIn(std::move(first.context), v->window_.get());

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // never drop an imgui.ini into the user's folder
  ImGui::StyleColorsDark();
  float scaleX = 1, scaleY = 1;
  glfwGetWindowContentScale(v->window_->window(), &scaleX, &scaleY);
  if (std::string why = loadViewerFont(std::max(scaleX, scaleY)); !why.empty())
    std::fprintf(stderr, "note: %s\n", why.c_str());
  v->installCallbacks();  // first, so ImGui's callbacks chain to ours
  ImGui_ImplGlfw_InitForOpenGL(v->window_->window(), true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  v->imguiReady_ = true;

  v->examples_ = listExamples(findExamplesDir());
  v->warmer_ = std::make_shared<ShaderWarmer>();
  v->worker_ = std::make_unique<session::SurfaceWorker>(
      v->session_.prepareOptions(), [] { glfwPostEmptyEvent(); },
      [warmer = v->warmer_](const Scene& s, const PreparedSurface& p) { warmer->warm(s, p); },
      [warmer = v->warmer_] { warmer->stop(); },
      [warmer = v->warmer_](const Scene& s) { warmer->warmPasses(s); });
  v->setScene(options.scene, {});
  v->sceneFile_ = options.sceneFile;
  if (options.exampleIndex >= 0 && std::size_t(options.exampleIndex) < v->examples_.size()) {
    v->exampleIndex_ = options.exampleIndex;
    v->relabel();  // the start label
    v->stats_.example = v->startLabel_;
  }
  v->startLanguage_ = i18n::currentLanguage();
  if (options.kiosk) {
    v->panel_.kiosk = options.kiosk;
    v->openGallery();
    // The formula keyboard never gives the formula box the focus: the interpreters for
    // first pictures are wanted from the start.
    v->interpretersAsked_ = true;
    v->warmer_->wantInterpreters(v->session_.scene());
  }
  return v;
}

Viewer::~Viewer() {
  worker_.reset();  // joins: the worker posts GLFW events, so it goes before the window
  if (window_) window_->makeCurrent();
  if (imguiReady_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  view_.reset();
}

void Viewer::run() {
  while (!window_->shouldClose()) frame();
  if (options_.log) {
    for (int reduced = 0; reduced < 2; ++reduced) {
      if (traces_[reduced] == 0) continue;
      const double mean = traceMsTotal_[reduced] / traces_[reduced];
      std::printf("traces %s: %d, mean %.1f ms (%.1f fps) at %dx%d\n", reduced ? "reduced" : "full",
                  traces_[reduced], mean, 1000.0 / mean, stats_.width / (reduced ? lastScale_ : 1),
                  stats_.height / (reduced ? lastScale_ : 1));
    }
    std::fflush(stdout);
  }
  std::lock_guard lock(mutex_);
  closed_ = true;
  for (Pending& p : pending_) p.reply.set_value("error: the window was closed\n");
  pending_.clear();
  for (Waiting& w : waiting_) {
    if (w.reply) w.reply->set_value("error: the window was closed\n");
  }
  waiting_.clear();
}

bool Viewer::interacting() const {
  return dragButton_ >= 0 || sliderActive_ ||
         Clock::now() - lastWheel_ < std::chrono::milliseconds(250);
}

int Viewer::reducedScale(int width, int height) const {
  if (options_.dragScale > 0) return options_.dragScale;
  // The smallest divisor whose estimated trace fits a 30 fps budget.
  return interact::dragScale(msPerPixel_, width, height);
}

void Viewer::traceIfNeeded(int width, int height) {
  if (!view_->ready()) return;
  if (width != stats_.width || height != stats_.height) dirty_ = true;
  stats_.width = width;
  stats_.height = height;
  const bool moving = interacting();
  // A first picture (tape interpreter) is drawn at reduced resolution and not refined: the
  // formula's own shader follows and draws the full one.
  const bool quick = view_->showingQuick();
  int scale = 0;
  if (dirty_) {
    scale = moving ? reducedScale(width, height) : quick ? session_.quickScale(width, height) : 1;
  } else if (refine_ && !moving && !quick)
    scale = 1;
  if (scale == 0) return;
  const Scene& scene = session_.scene();
  RenderSettings settings = quick ? firstPictureSettings(scene.render) : scene.render;
  if (scale > 1) settings.samples = 1;  // a moving preview needs no supersampling
  view_->setBeamPass(warmer_->passesWarm(builtProgram_));
  const double ms = view_->trace(settings, scene.domain, width, height, scale);
  const double rays =
      double(width / scale) * double(height / scale) * settings.samples * settings.samples;
  if (quick)
    session_.quickDrawn(ms, rays);
  else
    msPerPixel_ = ms / rays;
  stats_.traceMs = ms;
  stats_.traceScale = scale;
  stats_.curvatureRange = view_->curvatureRange();
  stats_.gaussian = settings.shading.color == ColorMode::Gauss;
  if (!uncounted_) {
    ++traces_[scale > 1];
    traceMsTotal_[scale > 1] += ms;
  }
  uncounted_ = false;
  if (scale > 1) lastScale_ = scale;
  dirty_ = false;
  refine_ = scale > 1;
}

void Viewer::frame() {
  // Waiting for the worker is done in glfwWaitEvents: it posts an event when it finishes.
  const bool outputReady = !waiting_.empty() && !worker_->busy() && !buildAt_;
  const bool busy = dirty_ || uiFrames_ > 0 || outputReady;
  releaseHeldKeys();
  if (busy) {
    glfwPollEvents();
  } else if (refine_ || buildAt_) {
    glfwWaitEventsTimeout(0.03);  // a wheel pause or a typing pause is about to end
  } else {
    glfwWaitEventsTimeout(0.5);
  }
  // Right after the events are read: input queued while the last frame was busy (a long
  // compile, say) has been noted, so time the viewer itself spent is not a visitor's idleness.
  returnToStartIfIdle();
  holdQuickKeys();
  releaseWaitingInput();
  runPending();
  takeBuild();
  // Once the worker has compiled the interpreters, the first pictures' compile of them is
  // quicker; it runs beside the window's frames and wakes them when it is done.
  const bool sampling = session_.scene().render.tracing.method == TracingMethod::Sampling;
  if (!view_->interpretersWarm(sampling) && warmer_->interpretersWarm(sampling)) {
    int width = 0, height = 0;
    window_->framebufferSize(width, height);
    view_->warmInterpreters(session_.scene(), width, height, [] { glfwPostEmptyEvent(); });
  }
  if (view_->interpretersWarm(sampling) && !firstPicturesSaid_[sampling]) {
    firstPicturesSaid_[sampling] = true;
    if (options_.log) {
      std::printf("first pictures ready\n");
      std::fflush(stdout);
    }
  }

  int width = 0, height = 0;
  window_->framebufferSize(width, height);
  if (width <= 0 || height <= 0) return;  // minimized

  const auto frameStart = Clock::now();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  replayMouseButtons();
  ImGui::NewFrame();
  stats_.fps = fps_;
  const Scene before = session_.scene();
  Scene edited = before;  // what the panel's widgets change this frame
  PanelResult panel;
  if (panelVisible_) panel = drawPanel(edited, panel_, stats_);
  if (options_.kiosk) drawFormulaKeyboard(panel_, panel);
  if (gallery_.visible) {
    if (const int picked = drawGallery(gallery_, exampleIndex_); picked >= 0) showExampleAt(picked);
  }
  panel_.formulaFocus.endFrame();
  gallery_.searchFocus.endFrame();
  // Under the pointer, over the picture and while nothing is dragged or rebuilt: what lies
  // there (src/probe).
  if (session_.prepared() && dragButton_ < 0 && !ImGui::GetIO().WantCaptureMouse &&
      session_.preparedScene().formula == session_.scene().formula && !buildAt_) {
    int windowWidth = 0, windowHeight = 0;
    glfwGetWindowSize(window_->window(), &windowWidth, &windowHeight);
    if (hover_.update(session_.scene(), cursorX_, cursorY_, windowWidth, windowHeight) &&
        options_.log) {
      std::printf("%s\n", hover_.logLine().c_str());
      std::fflush(stdout);
    }
    hover_.draw();
  } else {
    hover_.clear();
  }
  // A sweeping play button counts as a drag: reduced-resolution traces keep it fluid.
  sliderActive_ = panel.sliderActive || panel.animating;
  if (panel.languageChanged) relabel();
  if (panel.exportMesh) startMeshExport();
  if (panel.printPage) startPrint();
  // The formula box has the focus: the interpreters for first pictures are wanted now.
  if (!interpretersAsked_ && ImGui::GetIO().WantTextInput) {
    interpretersAsked_ = true;
    warmer_->wantInterpreters(session_.scene());
  }
  if (edited != before) {
    // Refused (a value a .surf would refuse): the session keeps the last scene that saves
    // and loads, and says why.
    if (std::string err = session_.edit(edited); !err.empty())
      stats_.status = panelError(err);
    else
      onSceneEdited(before);
  }
  if (panel.formulaEdited && panel_.formulaRefused && options_.log) {
    std::printf("refused: %s\n", panel_.formulaError.c_str());
    std::fflush(stdout);
  }
  if ((panel.formulaEdited || panel.formulaSubmitted) && panel_.formulaError.empty() &&
      panel_.formula != session_.scene().formula) {
    // Every valid prefix shows at once through the tape interpreter. Enter builds at once;
    // while typing, a pause of session::kTypingPauseMs does (the worker builds the latest
    // request only).
    showFirstPicture();
    if (panel.formulaSubmitted)
      applyTypedFormula();
    else
      buildAt_ = Clock::now() + std::chrono::milliseconds(session::kTypingPauseMs);
  }
  // After the panel has taken this frame's keys: a slow frame may hold several, and the
  // pause is measured from the last of them, not from a prefix typed before it.
  if (buildAt_ && Clock::now() >= *buildAt_) applyTypedFormula();
  ImGui::Render();
  traceIfNeeded(width, height);
  view_->present(width, height);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (windowShot_ && !worker_->busy()) captureWindow(width, height);
  window_->swapBuffers();
  answerWaiting();
  finishMeshExport();
  finishPrint();

  if (options_.log && !readyPrinted_ && session_.prepared() && !refine_ && !worker_->busy()) {
    readyPrinted_ = true;
    std::printf("ready %dx%d\n", width, height);
    std::fflush(stdout);
  }
  if (uiFrames_ > 0) --uiFrames_;
  stats_.frameMs = std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
  ++fpsFrames_;
  const double seconds = std::chrono::duration<double>(Clock::now() - fpsStart_).count();
  if (seconds >= 0.5) {
    fps_ = fpsFrames_ / seconds;
    fpsFrames_ = 0;
    fpsStart_ = Clock::now();
  }
}

}  // namespace zs::app
