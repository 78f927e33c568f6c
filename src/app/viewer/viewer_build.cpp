// Scene edits and surface builds: every edit goes to the session, which checks it and says
// what it rebuilds; requestBuild hands the session's build request to the worker, and
// takeBuild uploads finished builds on the main thread and hands them back to the session,
// which keeps the surface or, when the build failed, goes back to the one on screen.
#include <cstdio>

#include "app/viewer/viewer.hpp"
#include "i18n/translate.hpp"
#include "interact/parameter_range.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {

void Viewer::setScene(const Scene& scene, const std::string& exampleName) {
  if (std::string err = session_.loadScene(scene); !err.empty()) {
    stats_.status = panelError(err);
    return;
  }
  sceneReplaced(exampleName);
}

void Viewer::sceneReplaced(const std::string& exampleName) {
  view_->endQuick();
  session_.endQuick();
  quickFormula_.clear();
  panel_.formula = session_.scene().formula;
  panel_.formulaError.clear();
  stats_.example = exampleName;
  requestBuild();
  dirty_ = true;
}

void Viewer::applyTypedFormula() {
  buildAt_.reset();
  if (!panel_.formulaError.empty() || panel_.formula == session_.scene().formula) return;
  const Scene prior = session_.scene();
  if (std::string err = session_.setFormula(panel_.formula); !err.empty()) {
    panel_.formulaError = err;
    return;
  }
  onSceneEdited(prior);
}

void Viewer::showFirstPicture() {
  if (!session_.prepareQuick(panel_.formula).empty()) return;  // the build will show it
  if (!view_->showQuick(*session_.quickSurface())) return;
  quickFormula_ = panel_.formula;
  dirty_ = true;
  uncounted_ = true;
  if (options_.log) {
    std::printf("first picture %s\n", quickFormula_.c_str());
    std::fflush(stdout);
  }
}

void Viewer::requestBuild() {
  buildAt_.reset();
  if (std::optional<session::BuildRequest> request = session_.takeBuildRequest()) {
    worker_->submit(std::move(*request));
    stats_.building = true;
  }
}

void Viewer::onSceneEdited(const Scene& before) {
  const Scene& scene = session_.scene();
  // A new parameter value shows at once through the uniforms; the hierarchy built for the
  // old value follows from the worker.
  if (session_.prepared() && before.formula == scene.formula && before.params != scene.params) {
    const std::vector<double> values = paramValues(scene, session_.surface()->formula.graph);
    view_->setParams(std::vector<float>(values.begin(), values.end()));
  }
  requestBuild();
  dirty_ = true;
}

void Viewer::takeBuild() {
  std::optional<session::SurfaceWorker::Result> result = worker_->take();
  if (!result) return;
  stats_.building = worker_->busy();
  session::BuildResult& build = result->build;
  if (!session_.wants(build.id)) return;  // edits since have taken it back
  const std::string formula = build.scene.formula;
  const bool newFormula = formula != session_.preparedScene().formula;
  bool uploaded = false;
  if (const auto* surface = std::get_if<PreparedSurface>(&build.surface)) {
    // A first picture of a newer formula stays until that formula's own build arrives.
    const bool endsQuick = quickFormula_.empty() || formula == quickFormula_;
    if (std::string err = view_->upload(*surface, build.scene.render, endsQuick); !err.empty()) {
      build.surface = std::move(err);
    } else {
      uploaded = true;
      if (endsQuick) quickFormula_.clear();
    }
  }
  const std::string error = session_.finishBuild(std::move(build));
  if (uploaded) {
    if (newFormula) lastBuilt_ = std::chrono::steady_clock::now();
    const PreparedSurface& surface = *session_.surface();
    builtProgram_ = ShaderWarmer::programKey(surface.fragmentShader);
    dirty_ = true;
    uncounted_ = true;
    const std::vector<std::string>& names = surface.formula.graph.params();
    if (names != panel_.paramNames) {
      panel_.paramNames = names;
      panel_.paramRanges.clear();
      panel_.playing.clear();  // a new surface's parameters start at rest
      for (double v : surface.params) panel_.paramRanges.push_back(interact::paramRange(v));
    }
    stats_.buildMs = result->wallMs;
    stats_.leaves = surface.octree.leaves.size();
    stats_.nodes = surface.hierarchy.nodes.size();
    stats_.singularPoints =
        session_.scene().render.singular.enabled ? int(surface.singularPoints.size()) : -1;
    if (!session_.building() && panel_.formula == session_.preparedScene().formula)
      panel_.formulaError.clear();
  }
  if (!error.empty()) {
    // The last good surface stays on screen, and the session's scene has gone back to it.
    view_->endQuick();
    session_.endQuick();
    quickFormula_.clear();
    panel_.formulaError = error;
    stats_.status = i18n::tr("build failed; showing the last good surface");
    dirty_ = true;
  }
  if (options_.log) {
    std::printf(uploaded ? "built %s\n" : "build failed %s\n", formula.c_str());
    std::fflush(stdout);
  }
}

}  // namespace zs::app
