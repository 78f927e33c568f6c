#include "session/session.hpp"

#include <cstdio>
#include <exception>
#include <type_traits>
#include <utility>

#include "i18n/translate.hpp"
#include "interact/arcball.hpp"
#include "interpreter/interpreter_glsl.hpp"
#include "parser/parser.hpp"
#include "render/camera.hpp"
#include "render/program_variant.hpp"
#include "scene/scene_io.hpp"
#include "scene/schema.hpp"
#include "surfscript/surf_import.hpp"

namespace zs::session {
namespace {

// A formula's error at the caret, as `zeroset check` prints it.
std::string formulaError(std::string_view formula) {
  ParseResult parsed = parseFormula(formula);
  if (auto* err = std::get_if<ParseError>(&parsed)) return formatError(formula, *err);
  return {};
}

// "" when `scene` loads back from its own .surf text; otherwise the loader's message (a
// value outside its range, say).
std::string reloadError(const Scene& scene) {
  SceneResult reloaded = parseScene(saveScene(scene), "<view>");
  if (auto* err = std::get_if<SceneError>(&reloaded)) return formatSceneError(*err);
  return {};
}

constexpr Invalidation kBuilds = invalidates::Shader | invalidates::Geometry;

// The key light's vector a right drag turns: its position (point) or direction.
Vec3 keyLightVector(Scene& scene) {
  const Light* key = keyLight(scene.render.lights);
  return !key ? Vec3{} : key->kind == LightKind::Point ? key->position : key->direction;
}

}  // namespace

Session::Session(SessionOptions options)
    : options_(options), loaded_(scene_), dragStart_(scene_.render.camera) {}

// ---- edits ---------------------------------------------------------------------------------

std::string Session::replaceScene(Scene scene, std::string importNotes) {
  if (std::string error = formulaError(scene.formula); !error.empty()) return error;
  scene_ = std::move(scene);
  loaded_ = scene_;
  dragStart_ = scene_.render.camera;
  importNotes_ = std::move(importNotes);
  return {};
}

void Session::accept(Scene edited) {
  const bool cameraChanged = !(edited.render.camera == scene_.render.camera);
  scene_ = std::move(edited);
  if (cameraChanged) dragStart_ = scene_.render.camera;
}

std::string Session::loadFormula(std::string_view formula) {
  Scene scene;
  scene.formula = std::string(formula);
  return replaceScene(std::move(scene), {});
}

std::string Session::setFormula(std::string_view formula) {
  if (std::string error = formulaError(formula); !error.empty()) return error;
  scene_.formula = std::string(formula);
  return {};
}

std::string Session::addSurface(std::string_view formula) {
  return zs::addSurface(scene_, formula);
}

std::string Session::loadSurf(std::string_view text, std::string_view fileName) {
  SceneResult result = parseScene(text, fileName);
  if (auto* err = std::get_if<SceneError>(&result)) return formatSceneError(*err);
  return replaceScene(std::get<Scene>(std::move(result)), {});
}

std::optional<ImportResult> importForeignFile(const std::filesystem::path& path,
                                              std::string_view format) {
  if (format == "jsurf" || (format.empty() && jsurf::isJsurfPath(path.string())))
    return jsurf::loadJsurf(path);
  if (format == "pic" || (format.empty() && surfscript::isSurfScriptPath(path.string())))
    return surfscript::loadSurfScript(path);
  return std::nullopt;
}

std::string formatImportWarnings(const ImportedScene& imported) {
  std::string notes;
  for (const SceneError& w : imported.warnings) notes += formatSceneWarning(w);
  return notes;
}

std::string Session::replaceScene(ImportResult imported) {
  if (auto* err = std::get_if<SceneError>(&imported)) return formatSceneError(*err);
  ImportedScene& scene = std::get<ImportedScene>(imported);
  // What the other program shows differently is worth saying (notes()), but the load goes
  // ahead.
  std::string notes = formatImportWarnings(scene);
  return replaceScene(std::move(scene.scene), std::move(notes));
}

std::string Session::loadJsurf(std::string_view text, std::string_view fileName) {
  return replaceScene(jsurf::importJsurf(text, fileName));
}

std::string Session::loadSurfScript(std::string_view text, std::string_view fileName) {
  return replaceScene(surfscript::importSurfScript(text, fileName));
}

std::string Session::loadFile(const std::filesystem::path& path) {
  if (auto imported = importForeignFile(path)) return replaceScene(std::move(*imported));
  SceneResult loaded = zs::loadScene(path);
  if (auto* err = std::get_if<SceneError>(&loaded)) return formatSceneError(*err);
  return replaceScene(std::get<Scene>(std::move(loaded)), {});
}

std::string Session::loadScene(const Scene& scene, std::string notes) {
  return replaceScene(scene, std::move(notes));
}

std::string Session::applyOverrides(std::span<const std::string> assignments) {
  Scene edited = scene_;
  if (auto err = zs::applyOverrides(edited, assignments)) return formatSceneError(*err);
  if (std::string error = formulaError(edited.formula); !error.empty()) return error;
  accept(std::move(edited));
  return {};
}

std::string Session::setParam(std::string_view name, double value) {
  char number[32];
  std::snprintf(number, sizeof number, "%.17g", value);
  const std::string assignment = "params." + std::string(name) + "=" + number;
  Scene edited = scene_;
  if (auto err = zs::applyOverride(edited, assignment)) return formatSceneError(*err);
  scene_ = std::move(edited);
  return {};
}

std::string Session::edit(const Scene& edited) {
  if (edited == scene_) return {};
  if (edited.formula != scene_.formula) {
    if (std::string error = formulaError(edited.formula); !error.empty()) return error;
  }
  if (std::string error = reloadError(edited); !error.empty()) return error;
  accept(edited);
  return {};
}

// ---- the view ------------------------------------------------------------------------------

void Session::beginDrag() {
  dragStart_ = scene_.render.camera;
  dragLightStart_ = keyLightVector(scene_);
}

void Session::drag(double x0, double y0, double x1, double y1, int width, int height) {
  scene_.render.camera = interact::orbitCamera(dragStart_, {x0, y0, x1, y1, width, height});
}

void Session::dragLight(double x0, double y0, double x1, double y1, int width, int height) {
  Light* key = keyLight(scene_.render.lights);
  if (!key) return;
  const interact::DragPoints drag{x0, y0, x1, y1, width, height};
  // A light fixed to the camera turns in the world and is given back in camera coordinates.
  const Camera& view = scene_.render.camera;
  const bool fixedToCamera = scene_.render.lights.space == LightSpace::Camera;
  if (key->kind == LightKind::Point) {
    const Vec3 start = fixedToCamera ? cameraPointToWorld(view, dragLightStart_) : dragLightStart_;
    const Vec3 turned = interact::orbitPoint(view, start, drag);
    key->position = fixedToCamera ? worldPointToCamera(view, turned) : turned;
  } else {
    const Vec3 start = fixedToCamera ? cameraVectorToWorld(view, dragLightStart_) : dragLightStart_;
    const Vec3 turned = interact::orbitDirection(view, start, drag);
    key->direction = fixedToCamera ? worldVectorToCamera(view, turned) : turned;
  }
}

void Session::zoom(double wheelSteps) {
  scene_.render.camera = interact::zoomCamera(scene_.render.camera, wheelSteps);
}

int Session::key(int keyCode, int mods, std::string& message) {
  message.clear();
  const interact::KeyBinding* binding = interact::findBinding(keyCode, mods);
  if (!binding) return 0;
  return action(binding->action, message);
}

int Session::action(interact::Action action, std::string& message) {
  message.clear();
  if (action == interact::Action::ResetView) {
    resetView();
    message = "view reset";
    return 1;
  }
  Scene edited = scene_;
  if (!interact::applyAction(action, edited, message)) return 0;
  const Invalidation what = between(scene_, edited);
  scene_ = std::move(edited);
  return (what & kBuilds) ? 2 : 1;
}

void Session::resetView() {
  scene_.render.camera = dragStart_ = loaded_.render.camera;
  scene_.render.lights = loaded_.render.lights;
}

// ---- builds --------------------------------------------------------------------------------

Invalidation Session::between(const Scene& before, const Scene& after) const {
  return invalidation(before, after, surface_ ? &surface_->formula.graph.params() : nullptr);
}

Invalidation Session::pending() const {
  if (!surface_) return invalidates::Surface | invalidates::Variant;
  return between(preparedScene_, scene_);
}

bool Session::needsBuild() const {
  return (pending() & kBuilds) != 0;
}

PrepareOptions Session::prepareOptions() const {
  PrepareOptions options;
  options.validate = options_.validate;
  options.dialect = options_.dialect;
  return options;
}

std::optional<BuildRequest> Session::takeBuildRequest() {
  const Invalidation what = pending();
  if (!(what & kBuilds)) {
    // Nothing to build: the scene is good as it is, and a build still running is not
    // wanted any more (the edits that asked for it were taken back).
    preparedScene_ = scene_;
    requested_.reset();
    wanted_ = false;
    lastBuildError_.clear();
    return std::nullopt;
  }
  if (wanted_ && requested_ && !(between(*requested_, scene_) & kBuilds)) return std::nullopt;
  requested_ = scene_;
  latestId_ = nextId_++;
  wanted_ = true;
  return BuildRequest{latestId_, scene_, surface_ ? what : invalidates::Surface, surface_};
}

std::variant<PreparedSurface, std::string> Session::build(const BuildRequest& request,
                                                          const PrepareOptions& options) {
  try {
    if (!request.base) return prepareSurface(request.scene, options);
    return updateSurface(*request.base, request.scene, request.what, options);
  } catch (const std::exception& e) {  // a bug in zeroset: said, and the front end goes on
    return std::string("internal error in zeroset: ") + e.what() + "\n";
  }
}

void Session::rollBack() {
  if (!surface_) return;
  const Camera view = scene_.render.camera;
  scene_ = preparedScene_;
  scene_.render.camera = view;
}

std::string Session::finishBuild(BuildResult result) {
  const bool latest = result.id == latestId_;
  if (!wants(result.id)) return {};  // taken back since, or not ours
  if (latest) wanted_ = false;
  if (auto* err = std::get_if<std::string>(&result.surface)) {
    if (!latest) return {};  // a newer request follows: its result decides
    lastBuildError_ = *err;
    requested_.reset();
    // The edit that led here is undone: the scene goes back to the one on screen (its view
    // kept), so the panels, frames and later edits never pair it with another surface.
    rollBack();
    return *err;
  }
  PreparedSurface& surface = std::get<PreparedSurface>(result.surface);
  // WebGL2's texels of the hierarchy (the desktop's tracer packs its own, and says there
  // what its textures cannot hold).
  if (options_.dialect == ShaderDialect::Es300) {
    GpuHierarchy gpu;
    if (std::string error = toGpuHierarchy(surface.hierarchy.packed(), gpu); !error.empty()) {
      if (!latest) return {};
      lastBuildError_ = "error: " + error + "\n";
      requested_.reset();
      rollBack();
      return lastBuildError_;
    }
    gpu_ = std::move(gpu);
  }
  params_ = surface.paramsAsFloats();
  // Every parameter of the formula gets an entry, so sliders edit it and a save records it.
  const std::vector<std::string>& names = surface.formula.graph.params();
  for (std::size_t i = 0; i < names.size() && i < surface.params.size(); ++i) {
    for (Scene* scene : {&scene_, &result.scene}) {
      bool present = false;
      for (const auto& [key, value] : scene->params) present = present || key == names[i];
      if (!present) scene->params.emplace_back(names[i], surface.params[i]);
    }
  }
  surface_ = std::make_shared<const PreparedSurface>(std::move(surface));
  probe_.reset();
  preparedScene_ = std::move(result.scene);
  if (latest) {
    lastBuildError_.clear();
    requested_.reset();
  }
  ++generation_;
  return {};
}

std::string Session::prepare() {
  std::optional<BuildRequest> request = takeBuildRequest();
  if (!request) return {};
  auto surface = build(*request, prepareOptions());
  return finishBuild({request->id, std::move(request->scene), std::move(surface)});
}

// ---- first pictures ------------------------------------------------------------------------

int Session::quickScale(int width, int height) {
  if (!quick_) return interact::kFirstPictureMinScale;
  sizedInstructions_ = quick_->tape.instructions();
  sizedPolynomial_ = quick_->tape.polynomialOnly;
  return quickCost_.scale(width, height, sizedInstructions_, sizedPolynomial_);
}

void Session::quickDrawn(double ms, double pixels) {
  quickCost_.measured(ms, pixels, sizedInstructions_, sizedPolynomial_);
}

std::string Session::prepareQuick() {
  return prepareQuick(scene_.formula);
}

std::string Session::prepareQuick(std::string_view formula) {
  quick_.reset();
  Scene typed = scene_;
  typed.formula = std::string(formula);
  std::variant<QuickSurface, std::string> result;
  try {
    result = prepareQuickSurface(typed);
  } catch (const std::exception& e) {
    return std::string("internal error in zeroset: ") + e.what() + "\n";
  }
  if (auto* err = std::get_if<std::string>(&result)) return *err;
  QuickSurface quick = std::get<QuickSurface>(std::move(result));
  if (std::string error = toGpuHierarchy(quick.hierarchy.packed(), quickGpu_); !error.empty())
    return error;
  quick_ = std::move(quick);
  return {};
}

std::string Session::quickFragmentShader() const {
  if (!quick_) return {};
  return withVariantDefines(
      interpreterFragmentShader(quick_->sampling, quick_->tape.polynomialOnly, options_.dialect),
      ProgramVariant::of(firstPictureSettings(scene_.render)));
}

std::vector<std::string> Session::interpreterShaders() const {
  const bool sampling = scene_.render.tracing.method == TracingMethod::Sampling;
  std::vector<std::string> out;
  for (bool polynomialOnly : {true, false}) {
    out.push_back(
        withVariantDefines(interpreterFragmentShader(sampling, polynomialOnly, options_.dialect),
                           ProgramVariant::of(firstPictureSettings(scene_.render))));
  }
  return out;
}

const std::vector<std::uint32_t>& Session::quickTape() const {
  static const std::vector<std::uint32_t> none;
  return quick_ ? quick_->tape.texels : none;
}

FrameUniforms Session::quickFrame(int width, int height) const {
  const std::vector<float> params =
      quick_ ? std::vector<float>(quick_->params.begin(), quick_->params.end())
             : std::vector<float>();
  return frameOf(quickGpu_, params, quick_.has_value(), width, height);
}

// ---- what WebGL2 draws ---------------------------------------------------------------------

const std::string& Session::vertexShader() const {
  static const std::string none;
  return surface_ ? surface_->vertexShader : none;
}

std::string Session::fragmentShader() const {
  if (!surface_) return {};
  return withVariantDefines(surface_->fragmentShader, ProgramVariant::of(scene_.render));
}

FrameUniforms Session::frame(int width, int height) const {
  return frameOf(gpu_, params_, surface_ != nullptr, width, height);
}

FrameUniforms Session::frameOf(const GpuHierarchy& hierarchy, std::span<const float> params,
                               bool drawn, int width, int height) const {
  FrameInputs in;
  in.hierarchy = &hierarchy;
  in.params = params;
  in.width = width;
  in.height = height;
  in.proxy = Proxy::Box;
  // The automatic range needs a read-back of curvature values that WebGL2 cannot render
  // into without an extension; the page uses the scene's range, or 1.
  in.curvatureRange = scene_.render.shading.curvatureRange;
  FrameUniforms frame = frameUniforms(scene_.render, scene_.domain, in);
  if (!drawn) frame.vertices = 0;
  return frame;
}

std::variant<ProbeResult, std::string> Session::probe(int x, int y, int width, int height) const {
  if (!surface_) return std::string("nothing is drawn yet");
  // Made at the first probe of a surface: a front end that never hovers never pays for it.
  if (!probe_ || !probe_->sameSurfaces(scene_)) probe_ = std::make_unique<SceneProbe>(scene_);
  return probe_->pixel(scene_, width, height, x, y);
}

// ---- what the panels show ------------------------------------------------------------------

std::string Session::sceneText() const {
  return saveScene(scene_);
}

namespace {

// The first prefix that a key starts with names its section; N_ marks the names for
// translation where they are shown.
struct GroupRule {
  std::string_view prefix;
  std::string_view group;
};
constexpr std::string_view kGroups[] = {N_("Surface"),    N_("Tracing"),   N_("Domain"),
                                        N_("Camera"),     N_("Lights"),    N_("Materials"),
                                        N_("Highlights"), N_("Colouring"), N_("Cross-sections"),
                                        N_("Volume"),     N_("More")};
constexpr GroupRule kGroupRules[] = {
    {"surface", kGroups[0]},   {"tracing", kGroups[1]},    {"samples", kGroups[1]},
    {"opacity", kGroups[1]},   {"domain", kGroups[2]},     {"octree", kGroups[2]},
    {"image", kGroups[2]},     {"camera", kGroups[3]},     {"lights", kGroups[4]},
    {"materials", kGroups[5]}, {"highlights", kGroups[6]}, {"reflection", kGroups[6]},
    {"shading", kGroups[7]},   {"background", kGroups[7]}, {"clip", kGroups[8]},
    {"render", kGroups[9]},    {"volume", kGroups[9]},
};

}  // namespace

std::string_view panelGroup(std::string_view key) {
  for (const GroupRule& rule : kGroupRules) {
    if (key.starts_with(rule.prefix)) return rule.group;
  }
  return kGroups[std::size(kGroups) - 1];
}

std::span<const std::string_view> panelGroups() {
  return kGroups;
}

namespace {

// One schema key's range and current value in `scene`, as the panels show it.
Setting settingOf(const scene_detail::KeySpec& spec, Scene& scene, std::string key) {
  using namespace scene_detail;
  Setting s;
  s.key = std::move(key);
  s.group = std::string(panelGroup(s.key));
  s.lo = spec.range.lo;
  s.hi = spec.range.hi;
  s.loOpen = spec.range.loOpen;
  s.hiOpen = spec.range.hiOpen;
  std::visit(
      [&](const auto& field) {
        using F = std::decay_t<decltype(field)>;
        if constexpr (std::is_same_v<F, BoolRef>) {
          s.type = "bool";
          s.value = {field(scene) ? 1.0 : 0.0};
        } else if constexpr (std::is_same_v<F, IntRef> || std::is_same_v<F, SizeRef>) {
          s.type = "int";
          s.value = {double(field(scene))};
        } else if constexpr (std::is_same_v<F, RealRef>) {
          s.type = "real";
          s.value = {field(scene)};
        } else if constexpr (std::is_same_v<F, VecRef>) {
          s.type = "vec3";
          const Vec3& v = field(scene);
          s.value = {v[0], v[1], v[2]};
        } else if constexpr (std::is_same_v<F, FunctionRef>) {
          s.type = "function";
          s.choice = field(scene);
        } else {
          s.type = "enum";
          for (std::string_view name : field.names) s.choices.emplace_back(name);
          const int index = field.get(scene);
          if (index >= 0 && index < int(s.choices.size())) s.choice = s.choices[std::size_t(index)];
        }
      },
      spec.field);
  return s;
}

}  // namespace

std::vector<Setting> Session::settings() const {
  std::vector<Setting> out;
  Scene scene = scene_;  // the schema's fields address a mutable Scene
  for (const scene_detail::KeySpec& spec : scene_detail::keySpecs()) {
    if (spec.legacyLight >= 0) continue;  // old names, read only
    out.push_back(settingOf(spec, scene, std::string(spec.name)));
  }
  return out;
}

std::vector<std::vector<Setting>> Session::listEntries(std::string_view name) const {
  std::vector<std::vector<Setting>> out;
  const scene_detail::ListSpec* list = scene_detail::findList(name);
  if (!list) return out;
  for (std::size_t i = 0; i < list->size(scene_); ++i) {
    // The entry keys address the first element of a scene whose list holds just this one.
    Scene scratch;
    list->entry(scene_, i, scratch);
    std::vector<Setting> entry;
    for (const scene_detail::KeySpec& spec : list->keys) {
      entry.push_back(settingOf(
          spec, scratch,
          std::string(list->name) + "." + std::to_string(i + 1) + "." + std::string(spec.name)));
    }
    out.push_back(std::move(entry));
  }
  return out;
}

std::vector<std::pair<std::string, double>> Session::params() const {
  std::vector<std::pair<std::string, double>> out;
  if (!surface_) return out;
  const auto& names = surface_->formula.graph.params();
  for (std::size_t i = 0; i < names.size() && i < surface_->params.size(); ++i)
    out.emplace_back(names[i], surface_->params[i]);
  return out;
}

std::string Session::notes() const {
  std::string notes = importNotes_;
  if (surface_) notes += surface_->methodWarning + surface_->formulaNote + surface_->singularNote;
  return notes;
}

std::string Session::method() const {
  if (!surface_) return {};
  switch (surface_->method) {
    case TracingMethod::Bernstein:
      return "bernstein";
    case TracingMethod::Sampling:
      return "sampling";
    default:
      return "interval";
  }
}

}  // namespace zs::session
