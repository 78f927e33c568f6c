#include "app/repl/headless_target.hpp"

#include "app/repl/scene_edit.hpp"
#include "pipeline/load_surface.hpp"
#include "render/image.hpp"

namespace zs::app {

HeadlessTarget::HeadlessTarget(std::filesystem::path outputDir)
    : outputDir_(std::move(outputDir)) {}

HeadlessTarget::~HeadlessTarget() {
  if (context_) context_->makeCurrent();
  tracer_.reset();  // its GL objects go while their context is current
}

std::string HeadlessTarget::render(const std::filesystem::path& path) {
  if (std::string err = session_.prepare(); !err.empty()) return err;
  if (!context_) {
    ContextResult ctx = createHeadlessContext(Backend::Egl);
    if (!ctx.context) ctx = createHeadlessContext(Backend::OsMesa);
    if (!ctx.context) return "error: no offscreen GL context: " + ctx.error + "\n";
    context_ = std::move(ctx.context);
    tracer_ = std::make_unique<RayTracer>();
  }
  if (loadedGeneration_ != session_.generation()) {
    if (std::string err = loadSurface(*tracer_, *session_.surface(), session_.scene().render);
        !err.empty())
      return err;
    loadedGeneration_ = session_.generation();
  }
  const Scene& scene = session_.scene();
  Frame frame = tracer_->render(scene.render, scene.domain, scene.width, scene.height);
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
      if (std::string err = applyPromptEdit(command, session_); !err.empty()) return err;
      // Built before the picture: an edit the pipeline refuses is undone by the session,
      // and no picture is written for it.
      if (std::string err = session_.prepare(); !err.empty()) return err;
      std::string notes = command.kind == PromptCommand::Kind::Load ? session_.notes() : "";
      return notes + render(nextFreePath(outputDir_, "zeroset", ".png"));
    }
    case PromptCommand::Kind::Png:
      return render(command.arg);
    case PromptCommand::Kind::Save: {
      std::string err = writeSceneFile(command.arg, session_.scene());
      return err.empty() ? "saved: " + command.arg + "\n" : err;
    }
    default:
      return {};
  }
}

}  // namespace zs::app
