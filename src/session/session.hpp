#pragma once
// The session stage: one scene being looked at and edited, and the surface prepared for it.
// Every front end holds one — the viewer window, the prompt (with or without a window),
// `render --animate`, the web page — and only wires its input and output to it. Takes edits
// (a formula, a .surf or .jsurf file, `--set` assignments, a parameter, a panel's edit, a
// drag, a wheel step, a key), checks each as the command line does, and decides what it
// rebuilds from the schema (scene/invalidation.hpp); puts out the prepared surface
// (pipeline.hpp) of the scene, or, when a build fails, goes back to the last good one. A
// front end that builds on a worker thread asks for a BuildRequest, runs build() there and
// hands the result to finishBuild(); the others call prepare(). Every edit that fails leaves
// the scene and the prepared surface as they were and returns the positioned message (""
// on success). No GL, no emscripten, no ImGui.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "interact/key_bindings.hpp"
#include "interact/trace_budget.hpp"
#include "jsurf/jsurf.hpp"
#include "pipeline/pipeline.hpp"
#include "pipeline/quick_surface.hpp"
#include "probe/probe.hpp"
#include "render/frame_uniforms.hpp"
#include "render/hierarchy_gpu.hpp"
#include "scene/invalidation.hpp"
#include "scene/scene.hpp"

namespace zs::session {

// A file of another program's, by its extension — SURFER's .jsurf, surf's .pic script —
// or as `format` says ("jsurf", "pic") whatever its name, imported; nothing for any other
// file (a .surf scene, say).
std::optional<ImportResult> importForeignFile(const std::filesystem::path& path,
                                              std::string_view format = {});

// The warnings of an import, as the command line prints them.
std::string formatImportWarnings(const ImportedScene& imported);

// How long typing must pause before the typed formula is built (its first picture by the
// tape interpreter comes at every keystroke): every front end with a formula field waits
// this long. Shorter, a build starts between the keys of a steady typist and competes with
// the first pictures for the CPU (llvmpipe, and the page, whose build runs on its thread).
inline constexpr int kTypingPauseMs = 350;

// One key of the .surf schema (scene/schema.hpp) as the panels show it.
struct Setting {
  std::string key;        // as --set takes it: "tracing.epsilon", "lights.source.2.intensity"
  std::string type;       // "bool", "int", "real", "vec3", "enum" or "function"
  double lo = 0, hi = 0;  // the allowed range (each component of a vec3)
  bool loOpen = false, hiOpen = false;
  std::vector<std::string> choices;  // enum only
  std::vector<double> value;         // the current value: 1 number (bool: 0/1), or 3
  std::string choice;                // enum: the current name; function: its text
  std::string group;                 // the panel section it is shown in (panelGroup)
};

// The panel section a key of the schema (or a list: "lights.source") is shown in, in
// English ("Tracing", "Lights"); both panels, the viewer's and the page's, group by it.
std::string_view panelGroup(std::string_view key);
// The sections in the order the panels show them.
std::span<const std::string_view> panelGroups();

struct SessionOptions {
  // GLSL for the desktop's GL 3.3, or GLSL ES 3.00 for WebGL2 (pipeline.hpp).
  ShaderDialect dialect = ShaderDialect::Gl330;
  bool validate = true;  // glslang on the built shaders (not in the web build)
};

// What a build on another thread needs: the scene, what it invalidates beyond `base` (the
// surface on screen, null for none) and the request's number.
struct BuildRequest {
  std::uint64_t id = 0;
  Scene scene;
  Invalidation what = invalidates::Surface;
  std::shared_ptr<const PreparedSurface> base;
};

struct BuildResult {
  std::uint64_t id = 0;
  Scene scene;  // the request's
  std::variant<PreparedSurface, std::string> surface;
};

class Session {
 public:
  explicit Session(SessionOptions options = {});

  // ---- edits: "" or the message; on failure nothing changes ---------------------------
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
  // A surf script's text (.pic; docs/surf.md): the scene of its last draw_surface.
  std::string loadSurfScript(std::string_view text, std::string_view fileName);
  // A .surf, .jsurf or .pic file (by its extension), read from disk.
  std::string loadFile(const std::filesystem::path& path);
  // A scene made elsewhere (the command line's, a gallery example): replaces this one.
  std::string loadScene(const Scene& scene, std::string notes = {});
  // `--set KEY=VALUE` assignments, checked together as on the command line.
  std::string applyOverrides(std::span<const std::string> assignments);
  // One parameter's value (a slider).
  std::string setParam(std::string_view name, double value);
  // Any edit of the whole scene (a panel's widgets): refused, with the loader's message,
  // when its .surf text would not load back, so a saved view always loads.
  std::string edit(const Scene& edited);

  // ---- the view: camera and key light --------------------------------------------------
  // Pointer drags orbit the camera about its target (interact/arcball.hpp): positions in
  // pixels from the view's top-left, the view's size in the same pixels.
  void beginDrag();
  void drag(double x0, double y0, double x1, double y1, int width, int height);
  // The same drag turning the key light (the viewer's right button) instead of the camera.
  void dragLight(double x0, double y0, double x1, double y1, int width, int height);
  void zoom(double wheelSteps);
  // The viewer's keys (interact/key_bindings.hpp; GLFW's key codes, which are the upper-case
  // letters, and GLFW_MOD_SHIFT = 1) that edit the scene or reset the view. Returns the
  // effect: 0 none (no such key, or one the front end handles), 1 redraw, 2 prepare;
  // `message` says what changed.
  int key(int keyCode, int mods, std::string& message);
  // An editing action (the same table) as key() applies it.
  int action(interact::Action action, std::string& message);
  // Back to the camera and the lights the scene was loaded with.
  void resetView();

  // ---- builds ---------------------------------------------------------------------------
  // What the scene asks of the CPU stages beyond the surface on screen (all of it when
  // there is none): Shader or Geometry need a build, Variant and Frame only a redraw.
  Invalidation pending() const;
  bool needsBuild() const;
  // Builds what pending() says here and now; when it fails, the scene goes back to the one
  // of the surface on screen (the view kept), so the failed edit is undone as a whole.
  std::string prepare();
  // For a build on another thread: the request, when the scene needs one that is not asked
  // for yet (null otherwise; an edit that needs no build is taken as good at once).
  std::optional<BuildRequest> takeBuildRequest();
  // Runs a request (any thread): the stages it invalidates, over its base.
  static std::variant<PreparedSurface, std::string> build(const BuildRequest& request,
                                                          const PrepareOptions& options);
  PrepareOptions prepareOptions() const;
  // A finished build: a surface that succeeded goes on screen, unless an edit since has
  // made it unwanted (the scene went back to the one on screen); the latest request's error
  // takes the scene back to the surface on screen. "" or that error.
  std::string finishBuild(BuildResult result);
  // A build asked for and not finished yet.
  bool building() const { return wanted_; }
  // Whether finishBuild would take the result of request `id` (a front end that uploads a
  // surface before handing it back asks first).
  bool wants(std::uint64_t id) const { return wanted_ && id <= latestId_; }

  bool prepared() const { return surface_ != nullptr; }
  // The surface on screen (null before the first build) and the scene it was made from.
  const PreparedSurface* surface() const { return surface_.get(); }
  const Scene& preparedScene() const { return preparedScene_; }
  // Counts the surfaces put on screen: the page uploads the hierarchy when it changes.
  int generation() const { return generation_; }
  // The error of the latest build ("" when it is on screen).
  const std::string& lastBuildError() const { return lastBuildError_; }

  // ---- the first picture of a typed formula (docs/interpreter.md) ----------------------
  // By the tape interpreter, for the front end to show while the build's own shader
  // compiles: "" when it was made, else why not (the front end then waits for the build).
  // It changes nothing prepare() made. `formula` replaces the scene's for the picture only.
  std::string prepareQuick();
  std::string prepareQuick(std::string_view formula);
  bool quickPrepared() const { return quick_.has_value(); }
  const QuickSurface* quickSurface() const { return quick_ ? &*quick_ : nullptr; }
  void endQuick() { quick_.reset(); }
  // The quick surface's tape has only polynomial operations (the interpreter with the short
  // dispatch runs it: interpreterShaders()[0]).
  bool quickPolynomialOnly() const { return quick_ && quick_->tape.polynomialOnly; }
  // The interpreter's fragment shader for the quick surface (the same for every formula of
  // one method kind and dispatch, so it compiles once), with the scene's variant.
  std::string quickFragmentShader() const;
  // The divisor of each side for the quick surface's first picture at width x height, from
  // the first pictures drawn so far (interact/trace_budget.hpp), and what one of them cost.
  int quickScale(int width, int height);
  void quickDrawn(double ms, double pixels);  // the picture sized by the last quickScale
  // Every interpreter shader the scene's method can use (polynomial dispatch, every
  // operation), with the scene's variant: compiled in the background ahead of typing.
  std::vector<std::string> interpreterShaders() const;
  const std::vector<std::uint32_t>& quickTape() const;
  const GpuHierarchy& quickHierarchy() const { return quickGpu_; }
  // frame()'s uniforms for the quick surface.
  FrameUniforms quickFrame(int width, int height) const;

  // ---- what a WebGL2 front end draws -----------------------------------------------------
  const std::string& vertexShader() const;
  // The fragment shader with the #define lines of the scene's variant (lights, coloring,
  // supersampling, hits, reflection): render/program_variant.hpp.
  std::string fragmentShader() const;
  // (GLSL ES sessions only: the desktop's tracer packs the hierarchy itself.)
  const GpuHierarchy& hierarchy() const { return gpu_; }
  // Every uniform of one frame of width x height pixels (the full picture, also when it is
  // drawn in tiles), and the proxy's vertex count (0: nothing to draw).
  FrameUniforms frame(int width, int height) const;

  // What lies under pixel (x, y) of a width x height view of the prepared surface
  // (probe/probe.hpp): the hover readout.
  std::variant<ProbeResult, std::string> probe(int x, int y, int width, int height) const;

  const Scene& scene() const { return scene_; }
  // The scene as loaded (what resetView goes back to).
  const Scene& loadedScene() const { return loaded_; }
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
  std::string replaceScene(ImportResult imported);
  // Takes `edited` as the scene (the camera it brings becomes the one drags start from).
  void accept(Scene edited);
  // Invalidation between two scenes as far as the prepared surface's formula goes.
  Invalidation between(const Scene& before, const Scene& after) const;
  // Back to the scene of the surface on screen, keeping the view.
  void rollBack();
  // A frame's uniforms over this hierarchy and parameters (nothing drawn unless `drawn`).
  FrameUniforms frameOf(const GpuHierarchy& hierarchy, std::span<const float> params, bool drawn,
                        int width, int height) const;

  SessionOptions options_;
  Scene scene_;
  Scene loaded_;  // as loaded: what resetView goes back to
  Camera dragStart_;
  Vec3 dragLightStart_{};  // the key light's position (point) or direction at the drag's start
  std::shared_ptr<const PreparedSurface> surface_;
  Scene preparedScene_;             // the scene surface_ was prepared from: the last good one
  std::optional<Scene> requested_;  // the scene of the latest request handed out
  std::uint64_t nextId_ = 1, latestId_ = 0;
  bool wanted_ = false;  // the latest request is still wanted
  std::string lastBuildError_;
  mutable std::unique_ptr<SceneProbe> probe_;  // scene_'s surfaces, made at their first probe
  GpuHierarchy gpu_;
  std::vector<float> params_;
  std::optional<QuickSurface> quick_;
  interact::FirstPictureCost quickCost_;
  int sizedInstructions_ = 0;  // the tape of the picture quickScale sized last
  bool sizedPolynomial_ = true;
  GpuHierarchy quickGpu_;
  std::string importNotes_;
  int generation_ = 0;
};

}  // namespace zs::session
