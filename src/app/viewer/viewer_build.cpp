// Scene edits and surface builds: every change to the scene goes through onSceneEdited,
// which refuses values a .surf would refuse and decides between a redraw and a rebuild on
// the worker; takeBuild uploads finished builds on the main thread, or, when a build
// failed, puts the scene back to the surface still on screen.
#include <algorithm>
#include <cstdio>

#include "app/repl/scene_edit.hpp"
#include "app/viewer/viewer.hpp"
#include "i18n/translate.hpp"
#include "interact/parameter_range.hpp"
#include "parser/parser.hpp"
#include "pipeline/quick_surface.hpp"

namespace zs::app {
namespace {

bool needsBuild(const Scene& a, const Scene& b) {
  return a.formula != b.formula || a.level != b.level || a.params != b.params ||
         a.domain != b.domain ||
         a.octree != b.octree || a.render.tracing.method != b.render.tracing.method ||
         a.render.mode != b.render.mode ||  // a volume is the interval method's program
         a.render.singular != b.render.singular ||  // the markers are part of the shader
         // so are the second derivatives that the curvature colorings need
         needsCurvature(a.render.shading.color) != needsCurvature(b.render.shading.color) ||
         // and the contour function
         a.render.shading.contours.enabled != b.render.shading.contours.enabled ||
         (a.render.shading.contours.enabled &&
          a.render.shading.contours.function != b.render.shading.contours.function) ||
         // and, for several surfaces, the others' functions and materials (lit by the
         // ambient light) and the intersection curves
         a.moreSurfaces != b.moreSurfaces ||
         (!b.moreSurfaces.empty() && (a.render.lights.ambient != b.render.lights.ambient ||
                                      a.render.intersection != b.render.intersection));
}

}  // namespace

void Viewer::setScene(const Scene& scene, const std::string& exampleName) {
  view_->endQuick();
  quickFormula_.clear();
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

void Viewer::showFirstPicture() {
  Scene typed = scene_;
  typed.formula = panel_.formula;
  auto quick = prepareQuickSurface(typed);
  const auto* surface = std::get_if<QuickSurface>(&quick);
  if (!surface || !view_->showQuick(*surface)) return;  // the build will show it
  quickFormula_ = typed.formula;
  quickInstructions_ = surface->tape.instructions();
  quickPolynomial_ = surface->tape.polynomialOnly;
  dirty_ = true;
  uncounted_ = true;
  if (options_.log) {
    std::printf("first picture %s\n", typed.formula.c_str());
    std::fflush(stdout);
  }
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
  if (result->scene.formula != built_.formula) lastBuilt_ = std::chrono::steady_clock::now();
  stats_.building = worker_->busy();
  const bool latest = result->id == worker_->lastSubmitted();
  std::string error;
  if (auto* err = std::get_if<std::string>(&result->surface)) {
    error = *err;
  } else {
    const PreparedSurface& surface = std::get<PreparedSurface>(result->surface);
    // A first picture of a newer formula stays until that formula's own build arrives.
    const bool endsQuick = quickFormula_.empty() || result->scene.formula == quickFormula_;
    error = view_->upload(surface, endsQuick);
    if (error.empty() && endsQuick) quickFormula_.clear();
    if (error.empty()) {
      built_ = result->scene;
      builtProgram_ = ShaderWarmer::programKey(surface.fragmentShader);
      hasSurface_ = true;
      dirty_ = true;
      uncounted_ = true;
      const std::vector<std::string>& names = surface.formula.graph.params();
      if (names != panel_.paramNames) {
        panel_.paramNames = names;
        panel_.paramRanges.clear();
        panel_.playing.clear();  // a new surface's parameters start at rest
        for (double v : surface.params) panel_.paramRanges.push_back(interact::paramRange(v));
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
      stats_.nodes = surface.hierarchy.nodes.size();
      stats_.singularPoints =
          scene_.render.singular.enabled ? int(surface.singularPoints.size()) : -1;
      if (latest && panel_.formula == built_.formula) panel_.formulaError.clear();
    }
  }
  if (latest) lastBuildError_ = error;
  if (!error.empty() && latest) {
    view_->endQuick();
    quickFormula_.clear();
    // The last good surface stays on screen, and the scene goes back to it.
    scene_.formula = built_.formula;
    scene_.params = built_.params;
    scene_.domain = built_.domain;
    scene_.octree = built_.octree;
    panel_.formulaError = error;
    stats_.status = i18n::tr("build failed; showing the last good surface");
  }
  if (options_.log) {
    std::printf(error.empty() ? "built %s\n" : "build failed %s\n", result->scene.formula.c_str());
    std::fflush(stdout);
  }
}

}  // namespace zs::app
