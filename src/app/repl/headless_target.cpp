#include "app/repl/headless_target.hpp"

#include <variant>

#include "pipeline/load_surface.hpp"
#include "app/repl/scene_edit.hpp"
#include "render/image.hpp"

namespace zs::app {

HeadlessTarget::HeadlessTarget(std::filesystem::path outputDir)
    : outputDir_(std::move(outputDir)) {}

HeadlessTarget::~HeadlessTarget() {
  if (context_) context_->makeCurrent();
  tracer_.reset();  // its GL objects go while their context is current
}

std::string HeadlessTarget::prepare(const Scene& scene) {
  if (builtScene_ && surface_ && builtScene_->formula == scene.formula &&
      builtScene_->params == scene.params && builtScene_->domain == scene.domain &&
      builtScene_->octree == scene.octree)
    return {};
  auto prepared = prepareSurface(scene);
  if (auto* err = std::get_if<std::string>(&prepared)) return *err;
  surface_ = std::get<PreparedSurface>(std::move(prepared));
  builtScene_ = scene;
  return {};
}

std::string HeadlessTarget::render(const std::filesystem::path& path) {
  if (std::string err = prepare(scene_); !err.empty()) return err;
  if (!context_) {
    ContextResult ctx = createHeadlessContext(Backend::Egl);
    if (!ctx.context) ctx = createHeadlessContext(Backend::OsMesa);
    if (!ctx.context) return "error: no offscreen GL context: " + ctx.error + "\n";
    context_ = std::move(ctx.context);
    tracer_ = std::make_unique<RayTracer>();
  }
  if (std::string err = loadSurface(*tracer_, *surface_); !err.empty()) return err;
  Frame frame = tracer_->render(scene_.render, scene_.domain, scene_.width, scene_.height);
  if (!frame.error.empty()) return "error: " + frame.error + "\n";
  if (std::string err = writePng(path.string(), frame.color); !err.empty())
    return "error: " + err + "\n";
  return "wrote " + path.string() + "\n";
}

std::string HeadlessTarget::run(const PromptCommand& command) {
  switch (command.kind) {
    case PromptCommand::Kind::Formula:
    case PromptCommand::Kind::Set:
    case PromptCommand::Kind::Load: {
      Scene next = scene_;
      if (std::string err = applyToScene(command, next); !err.empty()) return err;
      // Build before accepting, so a formula the octree refuses leaves the scene as it was.
      if (std::string err = prepare(next); !err.empty()) return err;
      scene_ = next;
      return render(nextFreePath(outputDir_, "zeroset", ".png"));
    }
    case PromptCommand::Kind::Png: return render(command.arg);
    case PromptCommand::Kind::Save: {
      std::string err = writeSceneFile(command.arg, scene_);
      return err.empty() ? "saved: " + command.arg + "\n" : err;
    }
    default: return {};
  }
}

}  // namespace zs::app
