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

#include "app/repl/scene_edit.hpp"
#include "parser/parser.hpp"

namespace zs::app {
namespace {

using Clock = std::chrono::steady_clock;

bool needsBuild(const Scene& a, const Scene& b) {
  return a.formula != b.formula || a.params != b.params || a.domain != b.domain ||
         a.octree != b.octree;
}

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
  glfwSwapInterval(0);  // llvmpipe frames are slow enough; vsync would only add latency
  v->view_ = std::make_unique<SurfaceView>();

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // never drop an imgui.ini into the user's folder
  ImGui::StyleColorsDark();
  v->installCallbacks();  // first, so ImGui's callbacks chain to ours
  ImGui_ImplGlfw_InitForOpenGL(v->window_->window(), true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  v->imguiReady_ = true;

  v->examples_ = listExamples(findExamplesDir());
  v->worker_ = std::make_unique<SurfaceWorker>([] { glfwPostEmptyEvent(); });
  v->setScene(options.scene, {});
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
  std::lock_guard lock(mutex_);
  closed_ = true;
  for (Pending& p : pending_) p.reply.set_value("error: the window was closed\n");
  pending_.clear();
  for (Waiting& w : waiting_) {
    if (w.reply) w.reply->set_value("error: the window was closed\n");
  }
  waiting_.clear();
}

void Viewer::setScene(const Scene& scene, const std::string& exampleName) {
  scene_ = scene;
  loaded_ = scene;
  panel_.formula = scene.formula;
  panel_.formulaError.clear();
  stats_.example = exampleName;
  requestBuild();
  dirty_ = true;
}

void Viewer::applyTypedFormula() {
  buildAt_.reset();
  if (!panel_.formulaError.empty() || panel_.formula == scene_.formula) return;
  const Scene prior = scene_;
  scene_.formula = panel_.formula;
  onSceneEdited(prior);
}

void Viewer::requestBuild() {
  buildAt_.reset();
  worker_->submit(scene_);
  stats_.building = true;
}

std::string Viewer::onSceneEdited(const Scene& before) {
  if (std::string err = checkScene(scene_); !err.empty()) {
    scene_ = before;  // refused: keep the last scene that saves and loads
    stats_.status = err;
    return err;
  }
  if (needsBuild(before, scene_)) {
    // A new parameter value shows at once through the uniforms; the hierarchy built for
    // the old value follows from the worker.
    if (before.formula == scene_.formula && before.params != scene_.params) {
      std::vector<float> values;
      for (const std::string& name : panel_.paramNames) {
        double v = kDefaultParamValue;
        for (const auto& [key, value] : scene_.params) {
          if (key == name) v = value;
        }
        values.push_back(float(v));
      }
      view_->setParams(values);
    }
    requestBuild();
  }
  dirty_ = true;
  return {};
}

void Viewer::takeBuild() {
  std::optional<SurfaceWorker::Result> result = worker_->take();
  if (!result) return;
  stats_.building = worker_->busy();
  const bool latest = result->id == worker_->lastSubmitted();
  std::string error;
  if (auto* err = std::get_if<std::string>(&result->surface)) {
    error = *err;
  } else {
    const PreparedSurface& surface = std::get<PreparedSurface>(result->surface);
    error = view_->upload(surface);
    if (error.empty()) {
      built_ = result->scene;
      hasSurface_ = true;
      dirty_ = true;
      const std::vector<std::string>& names = surface.formula.graph.params();
      if (names != panel_.paramNames) {
        panel_.paramNames = names;
        panel_.paramRanges.clear();
        for (double v : surface.params) panel_.paramRanges.push_back(paramRange(v));
      }
      // Every parameter gets an entry, so the sliders edit it and a save records it.
      for (std::size_t i = 0; i < names.size(); ++i) {
        const bool present = std::any_of(scene_.params.begin(), scene_.params.end(),
                                         [&](const auto& p) { return p.first == names[i]; });
        if (!present) scene_.params.emplace_back(names[i], surface.params[i]);
      }
      if (latest) built_.params = scene_.params;
      stats_.buildMs = result->wallMs;
      stats_.leaves = surface.octree.leaves.size();
      stats_.spheres = surface.hierarchy.nodes.size();
      if (latest && panel_.formula == built_.formula) panel_.formulaError.clear();
    }
  }
  if (latest) lastBuildError_ = error;
  if (!error.empty() && latest) {
    // The last good surface stays on screen, and the scene goes back to it.
    scene_.formula = built_.formula;
    scene_.params = built_.params;
    scene_.domain = built_.domain;
    scene_.octree = built_.octree;
    panel_.formulaError = error;
    stats_.status = "build failed; showing the last good surface";
  }
  if (options_.log) {
    std::printf(error.empty() ? "built %s\n" : "build failed %s\n", result->scene.formula.c_str());
    std::fflush(stdout);
  }
}

bool Viewer::interacting() const {
  return dragButton_ >= 0 || sliderActive_ ||
         Clock::now() - lastWheel_ < std::chrono::milliseconds(250);
}

int Viewer::reducedScale(int width, int height) const {
  if (options_.dragScale > 0) return options_.dragScale;
  if (msPerPixel_ <= 0) return 2;
  // The smallest divisor whose estimated trace fits a 30 fps budget.
  for (int s = 1; s < 4; ++s) {
    if (msPerPixel_ * double(width / s) * double(height / s) <= 33.0) return s;
  }
  return 4;
}

void Viewer::traceIfNeeded(int width, int height) {
  if (!view_->ready()) return;
  if (width != stats_.width || height != stats_.height) dirty_ = true;
  stats_.width = width;
  stats_.height = height;
  const bool moving = interacting();
  int scale = 0;
  if (dirty_) scale = moving ? reducedScale(width, height) : 1;
  else if (refine_ && !moving) scale = 1;
  if (scale == 0) return;
  RenderSettings settings = scene_.render;
  if (scale > 1) settings.samples = 1;  // a moving preview needs no supersampling
  const double ms = view_->trace(settings, scene_.domain, width, height, scale);
  const double samples = double(settings.samples) * settings.samples;
  msPerPixel_ = ms / (double(width / scale) * double(height / scale) * samples);
  stats_.traceMs = ms;
  stats_.traceScale = scale;
  dirty_ = false;
  refine_ = scale > 1;
}

void Viewer::frame() {
  // Waiting for the worker is done in glfwWaitEvents: it posts an event when it finishes.
  const bool outputReady = !waiting_.empty() && !worker_->busy() && !buildAt_;
  const bool busy = dirty_ || uiFrames_ > 0 || outputReady;
  if (busy) {
    glfwPollEvents();
  } else if (refine_ || buildAt_) {
    glfwWaitEventsTimeout(0.03);  // a wheel pause or a typing pause is about to end
  } else {
    glfwWaitEventsTimeout(0.5);
  }
  runPending();
  takeBuild();
  if (buildAt_ && Clock::now() >= *buildAt_) applyTypedFormula();

  int width = 0, height = 0;
  window_->framebufferSize(width, height);
  if (width <= 0 || height <= 0) return;  // minimized

  const auto frameStart = Clock::now();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  stats_.fps = fps_;
  const Scene before = scene_;
  PanelResult panel;
  if (panelVisible_) panel = drawPanel(scene_, panel_, stats_);
  sliderActive_ = panel.sliderActive;
  if (scene_ != before) onSceneEdited(before);
  if ((panel.formulaEdited || panel.formulaSubmitted) && panel_.formulaError.empty() &&
      panel_.formula != scene_.formula) {
    // Enter builds at once; while typing, a pause of 350 ms does (each valid prefix would
    // otherwise queue a build and a shader compile).
    if (panel.formulaSubmitted) applyTypedFormula();
    else buildAt_ = Clock::now() + std::chrono::milliseconds(350);
  }
  ImGui::Render();
  traceIfNeeded(width, height);
  view_->present(width, height);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  window_->swapBuffers();
  answerWaiting();

  if (options_.log && !readyPrinted_ && hasSurface_ && !refine_ && !worker_->busy()) {
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
