#pragma once
// The prompt without a display: takes prompt commands, keeps the current scene, and puts
// out PNG files rendered offscreen (EGL, or OSMesa when EGL is unavailable). Every change
// to the scene (a formula, :set, :load) renders the new picture into the output folder as
// zeroset-NNNN.png and answers "wrote PATH"; :png FILE renders to FILE, :save FILE writes
// the .surf. A command that fails leaves the scene as it was.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "pipeline/pipeline.hpp"
#include "app/repl/command.hpp"
#include "render/gl_context.hpp"
#include "render/ray_tracer.hpp"

namespace zs::app {

class HeadlessTarget final : public PromptTarget {
 public:
  explicit HeadlessTarget(std::filesystem::path outputDir);
  ~HeadlessTarget() override;
  std::string run(const PromptCommand& command) override;

 private:
  // Builds `scene` if its surface differs from the cached one; "" or the error text.
  std::string prepare(const Scene& scene);
  std::string render(const std::filesystem::path& path);

  std::filesystem::path outputDir_;
  Scene scene_;
  std::optional<Scene> builtScene_;
  std::optional<PreparedSurface> surface_;
  std::unique_ptr<GlContext> context_;  // created at the first render
  std::unique_ptr<RayTracer> tracer_;
};

}  // namespace zs::app
