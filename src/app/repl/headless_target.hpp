#pragma once
// The prompt without a display: takes prompt commands, carries them out on its session
// (session/session.hpp), and puts out PNG files rendered offscreen (EGL, or OSMesa when EGL
// is unavailable). Every change to the scene (a formula, :set, :load) renders the new
// picture into the output folder as zeroset-NNNN.png and answers "wrote PATH"; :png FILE
// renders to FILE, :save FILE writes the .surf. A command that fails leaves the scene and
// the picture as they were.
#include <filesystem>
#include <memory>
#include <string>

#include "app/repl/command.hpp"
#include "render/gl_context.hpp"
#include "render/ray_tracer.hpp"
#include "session/session.hpp"

namespace zs::app {

class HeadlessTarget final : public PromptTarget {
 public:
  explicit HeadlessTarget(std::filesystem::path outputDir);
  ~HeadlessTarget() override;
  std::string run(const PromptCommand& command) override;

 private:
  std::string render(const std::filesystem::path& path);

  std::filesystem::path outputDir_;
  session::Session session_;
  int loadedGeneration_ = 0;            // the session's surface in the tracer
  std::unique_ptr<GlContext> context_;  // created at the first render
  std::unique_ptr<RayTracer> tracer_;
};

}  // namespace zs::app
