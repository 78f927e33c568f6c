#pragma once
// The web page's core: holds one scene, takes what the page's controls ask for (a formula, a
// .surf or .jsurf file, `--set` assignments, a drag, a wheel step, a key), applies it with
// the same parsing, scene rules and validation as the command line, and puts out what WebGL2
// needs to draw the scene: the GLSL ES shaders (src/codegen, the same templates), the
// hierarchy's texels and every uniform of a frame (render/frame_uniforms.hpp). GL-free and
// free of emscripten: bindings.cpp exposes it to JavaScript, and the native tests drive it
// directly. Every edit that fails leaves the scene and the prepared surface as they were and
// returns the positioned message ("" on success).
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "interact/key_bindings.hpp"
#include "interact/trace_budget.hpp"
#include "pipeline/pipeline.hpp"
#include "pipeline/quick_surface.hpp"
#include "probe/probe.hpp"
#include "render/frame_uniforms.hpp"
#include "render/hierarchy_gpu.hpp"
#include "scene/scene.hpp"

namespace zs::web {

// One key of the .surf schema (scene/schema.hpp) as the page's panels show it.
struct Setting {
  std::string key;        // as --set takes it: "tracing.epsilon", "lights.source.2.intensity"
  std::string type;       // "bool", "int", "real", "vec3", "enum" or "function"
  double lo = 0, hi = 0;  // the allowed range (each component of a vec3)
  bool loOpen = false, hiOpen = false;
  std::vector<std::string> choices;  // enum only
  std::vector<double> value;         // the current value: 1 number (bool: 0/1), or 3
  std::string choice;                // enum: the current name; function: its text
};

class WebSession {
 public:
  WebSession();

  // The default scene with this formula (as `zeroset render FORMULA`).
  std::string loadFormula(std::string_view formula);
  // The formula only (the first surface's); every other setting stays.
  std::string setFormula(std::string_view formula);
  // One more surface drawn with the others (the URL's surface=), in its own colors.
  std::string addSurface(std::string_view formula);
  // A whole .surf text; `fileName` names it in errors.
  std::string loadSurf(std::string_view text, std::string_view fileName);
  // A SURFER .jsurf text; what zeroset shows differently goes to notes().
  std::string loadJsurf(std::string_view text, std::string_view fileName);
  // `--set KEY=VALUE` assignments, checked together as on the command line.
  std::string applyOverrides(std::span<const std::string> assignments);
  // One parameter's value (a slider).
  std::string setParam(std::string_view name, double value);

  // The CPU half of a frame for WebGL2 (pipeline.hpp with ShaderDialect::Es300): octree,
  // hierarchy, method, shaders. Needed after every edit above; a drag or a wheel step
  // needs none. When it fails, the scene goes back to that of the surface on screen (the
  // view kept), so the failed edit is undone as a whole.
  std::string prepare();
  bool prepared() const { return surface_.has_value(); }
  // Counts successful prepare() calls: the page uploads the hierarchy when it changes.
  int generation() const { return generation_; }

  // The first picture of the scene's formula by the tape interpreter (docs/interpreter.md),
  // for the page to show while prepare()'s own shader compiles: "" when it was made, else
  // why not (the page then waits for prepare()). It changes nothing prepare() made.
  std::string prepareQuick();
  bool quickPrepared() const { return quick_.has_value(); }
  // The quick surface's tape has only polynomial operations (the interpreter with the short
  // dispatch runs it: interpreterShaders()[0]).
  bool quickPolynomialOnly() const { return quick_ && quick_->tape.polynomialOnly; }
  // The interpreter's fragment shader for the quick surface (the same for every formula of
  // one method kind and dispatch, so the page compiles it once), with the scene's variant.
  std::string quickFragmentShader() const;
  // The divisor of each side for the quick surface's first picture at width x height, from
  // the first pictures drawn so far (the viewer's rule: interact/trace_budget.hpp), and what
  // one of them cost.
  int quickScale(int width, int height);
  void quickDrawn(double ms, double pixels);  // the picture sized by the last quickScale
  // Every interpreter shader the scene's method can use (polynomial dispatch, every
  // operation), with the scene's variant: what the page compiles in the background ahead of
  // the first keystroke.
  std::vector<std::string> interpreterShaders() const;
  const std::vector<std::uint32_t>& quickTape() const;
  const GpuHierarchy& quickHierarchy() const { return quickGpu_; }
  // frame()'s uniforms for the quick surface.
  FrameUniforms quickFrame(int width, int height) const;

  const std::string& vertexShader() const;
  // The fragment shader with the #define lines of the scene's variant (lights, coloring,
  // supersampling, hits, reflection): render/program_variant.hpp.
  std::string fragmentShader() const;
  const GpuHierarchy& hierarchy() const { return gpu_; }
  // Every uniform of one frame of width x height pixels (the full picture, also when the
  // page draws it in tiles), and the proxy's vertex count (0: nothing to draw).
  FrameUniforms frame(int width, int height) const;

  // Pointer drags orbit the camera about its target (interact/arcball.hpp): positions in CSS
  // pixels from the canvas' top-left, the canvas' size in the same pixels.
  void beginDrag();
  void drag(double x0, double y0, double x1, double y1, int width, int height);
  void zoom(double wheelSteps);
  // What lies under pixel (x, y) of a width x height view of the prepared surface
  // (probe/probe.hpp): the hover readout.
  std::variant<ProbeResult, std::string> probe(int x, int y, int width, int height) const;
  // The desktop viewer's keys (interact/key_bindings.hpp; GLFW's key codes, which are the
  // upper-case letters, and GLFW_MOD_SHIFT = 1). Returns the effect: 0 none, 1 redraw,
  // 2 prepare; `message` says what changed.
  int key(int keyCode, int mods, std::string& message);
  // Back to the camera the scene was loaded with.
  void resetView();

  const Scene& scene() const { return scene_; }
  // The scene as a complete .surf text (save, share links).
  std::string sceneText() const;
  // Every key of the scene schema with its range and current value, in file order.
  std::vector<Setting> settings() const;
  // The entries of a list of the scene ("lights.source", "clip.plane") in order, each as its
  // keys ("lights.source.N.KEY", N from 1, what applyOverrides takes); none for another name.
  std::vector<std::vector<Setting>> listEntries(std::string_view list) const;
  // Parameter names in the formula's order and their values (prepared surface's).
  std::vector<std::pair<std::string, double>> params() const;
  // Notes for the user: the method's fallback, a constant formula, what a .jsurf file
  // could not carry over. One per line; "" when there is nothing to say.
  std::string notes() const;
  // "bernstein", "interval" or "sampling": the method the prepared surface is traced with.
  std::string method() const;

 private:
  std::string replaceScene(Scene scene, std::string importNotes);
  // A frame's uniforms over this hierarchy and parameters (nothing drawn unless `drawn`).
  FrameUniforms frameOf(const GpuHierarchy& hierarchy, std::span<const float> params,
                        bool drawn, int width, int height) const;

  Scene scene_;
  Camera loadedCamera_;
  Camera dragStart_;
  std::optional<PreparedSurface> surface_;
  Scene preparedScene_;  // the scene surface_ was prepared from
  mutable std::unique_ptr<SceneProbe> probe_;  // scene_'s surfaces, made at their first probe
  GpuHierarchy gpu_;
  std::vector<float> params_;
  std::optional<QuickSurface> quick_;
  interact::FirstPictureCost quickCost_;
  int sizedInstructions_ = 0;     // the tape of the picture quickScale sized last
  bool sizedPolynomial_ = true;
  GpuHierarchy quickGpu_;
  std::string importNotes_;
  int generation_ = 0;
};

}  // namespace zs::web
