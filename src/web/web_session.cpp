#include "web/web_session.hpp"

#include <cstdio>
#include <exception>
#include <type_traits>
#include <utility>

#include "interact/arcball.hpp"
#include "interpreter/interpreter_glsl.hpp"
#include "jsurf/jsurf.hpp"
#include "parser/parser.hpp"
#include "render/program_variant.hpp"
#include "scene/scene_io.hpp"
#include "scene/schema.hpp"

namespace zs::web {
namespace {

// A formula's error at the caret, as `zeroset check` prints it.
std::string formulaError(std::string_view formula) {
  ParseResult parsed = parseFormula(formula);
  if (auto* err = std::get_if<ParseError>(&parsed)) return formatError(formula, *err);
  return {};
}

}  // namespace

WebSession::WebSession() : loadedCamera_(scene_.render.camera), dragStart_(loadedCamera_) {}

std::string WebSession::replaceScene(Scene scene, std::string importNotes) {
  if (std::string error = formulaError(scene.formula); !error.empty()) return error;
  scene_ = std::move(scene);
  loadedCamera_ = dragStart_ = scene_.render.camera;
  importNotes_ = std::move(importNotes);
  return {};
}

std::string WebSession::loadFormula(std::string_view formula) {
  Scene scene;
  scene.formula = std::string(formula);
  return replaceScene(std::move(scene), {});
}

std::string WebSession::setFormula(std::string_view formula) {
  if (std::string error = formulaError(formula); !error.empty()) return error;
  scene_.formula = std::string(formula);
  return {};
}

std::string WebSession::addSurface(std::string_view formula) {
  return zs::addSurface(scene_, formula);
}

std::string WebSession::loadSurf(std::string_view text, std::string_view fileName) {
  SceneResult result = parseScene(text, fileName);
  if (auto* err = std::get_if<SceneError>(&result)) return formatSceneError(*err);
  return replaceScene(std::get<Scene>(std::move(result)), {});
}

std::string WebSession::loadJsurf(std::string_view text, std::string_view fileName) {
  jsurf::ImportResult result = jsurf::importJsurf(text, fileName);
  if (auto* err = std::get_if<SceneError>(&result)) return formatSceneError(*err);
  jsurf::Imported imported = std::get<jsurf::Imported>(std::move(result));
  std::string notes;
  for (const SceneError& w : imported.warnings) notes += jsurf::formatWarning(w);
  return replaceScene(std::move(imported.scene), std::move(notes));
}

std::string WebSession::applyOverrides(std::span<const std::string> assignments) {
  Scene edited = scene_;
  if (auto err = zs::applyOverrides(edited, assignments)) return formatSceneError(*err);
  if (std::string error = formulaError(edited.formula); !error.empty()) return error;
  const bool cameraChanged = !(edited.render.camera == scene_.render.camera);
  scene_ = std::move(edited);
  if (cameraChanged) loadedCamera_ = dragStart_ = scene_.render.camera;
  return {};
}

std::string WebSession::setParam(std::string_view name, double value) {
  char number[32];
  std::snprintf(number, sizeof number, "%.17g", value);
  const std::string assignment = "params." + std::string(name) + "=" + number;
  Scene edited = scene_;
  if (auto err = zs::applyOverride(edited, assignment)) return formatSceneError(*err);
  scene_ = std::move(edited);
  return {};
}

std::string WebSession::prepare() {
  PrepareOptions options;
  options.validate = false;  // WebGL2 compiles, and reports what it rejects
  options.dialect = ShaderDialect::Es300;
  std::variant<PreparedSurface, std::string> result;
  try {
    result = prepareSurface(scene_, options);
  } catch (const std::exception& e) {  // a bug in zeroset: said, and the page goes on
    return std::string("internal error in zeroset: ") + e.what() + "\n";
  }
  if (auto* err = std::get_if<std::string>(&result)) {
    // The edit that led here is undone: the scene goes back to the one on screen (its view
    // kept), so the panels, frames and later edits never pair it with another surface.
    if (surface_) {
      const Camera view = scene_.render.camera;
      scene_ = preparedScene_;
      scene_.render.camera = view;
    }
    return *err;
  }
  PreparedSurface surface = std::get<PreparedSurface>(std::move(result));
  GpuHierarchy gpu;
  if (std::string error = toGpuHierarchy(surface.hierarchy.packed(), gpu); !error.empty())
    return "error: " + error + "\n";
  gpu_ = std::move(gpu);
  params_ = surface.paramsAsFloats();
  surface_ = std::move(surface);
  probe_.reset();
  preparedScene_ = scene_;
  ++generation_;
  return {};
}

const std::string& WebSession::vertexShader() const {
  static const std::string none;
  return surface_ ? surface_->vertexShader : none;
}

int WebSession::quickScale(int width, int height) {
  if (!quick_) return interact::kFirstPictureMinScale;
  sizedInstructions_ = quick_->tape.instructions();
  sizedPolynomial_ = quick_->tape.polynomialOnly;
  return quickCost_.scale(width, height, sizedInstructions_, sizedPolynomial_);
}

void WebSession::quickDrawn(double ms, double pixels) {
  quickCost_.measured(ms, pixels, sizedInstructions_, sizedPolynomial_);
}

std::string WebSession::prepareQuick() {
  quick_.reset();
  std::variant<QuickSurface, std::string> result;
  try {
    result = prepareQuickSurface(scene_);
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

std::string WebSession::quickFragmentShader() const {
  if (!quick_) return {};
  return withVariantDefines(
      interpreterFragmentShader(quick_->sampling, quick_->tape.polynomialOnly, ShaderDialect::Es300),
      ProgramVariant::of(firstPictureSettings(scene_.render)));
}

std::vector<std::string> WebSession::interpreterShaders() const {
  const bool sampling = scene_.render.tracing.method == TracingMethod::Sampling;
  std::vector<std::string> out;
  for (bool polynomialOnly : {true, false}) {
    out.push_back(withVariantDefines(
        interpreterFragmentShader(sampling, polynomialOnly, ShaderDialect::Es300),
        ProgramVariant::of(firstPictureSettings(scene_.render))));
  }
  return out;
}

const std::vector<std::uint32_t>& WebSession::quickTape() const {
  static const std::vector<std::uint32_t> none;
  return quick_ ? quick_->tape.texels : none;
}

FrameUniforms WebSession::quickFrame(int width, int height) const {
  const std::vector<float> params =
      quick_ ? std::vector<float>(quick_->params.begin(), quick_->params.end())
             : std::vector<float>();
  return frameOf(quickGpu_, params, quick_.has_value(), width, height);
}

std::string WebSession::fragmentShader() const {
  if (!surface_) return {};
  return withVariantDefines(surface_->fragmentShader, ProgramVariant::of(scene_.render));
}

FrameUniforms WebSession::frame(int width, int height) const {
  return frameOf(gpu_, params_, surface_.has_value(), width, height);
}

FrameUniforms WebSession::frameOf(const GpuHierarchy& hierarchy, std::span<const float> params,
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

std::variant<ProbeResult, std::string> WebSession::probe(int x, int y, int width,
                                                         int height) const {
  if (!surface_) return std::string("nothing is drawn yet");
  // Made at the first probe of a surface: a page that never hovers never pays for it.
  if (!probe_ || !probe_->sameSurfaces(scene_)) probe_ = std::make_unique<SceneProbe>(scene_);
  return probe_->pixel(scene_, width, height, x, y);
}

void WebSession::beginDrag() {
  dragStart_ = scene_.render.camera;
}

void WebSession::drag(double x0, double y0, double x1, double y1, int width, int height) {
  scene_.render.camera = interact::orbitCamera(dragStart_, {x0, y0, x1, y1, width, height});
}

void WebSession::zoom(double wheelSteps) {
  scene_.render.camera = interact::zoomCamera(scene_.render.camera, wheelSteps);
}

int WebSession::key(int keyCode, int mods, std::string& message) {
  message.clear();
  const interact::KeyBinding* binding = interact::findBinding(keyCode, mods);
  if (!binding) return 0;
  if (binding->action == interact::Action::ResetView) {
    resetView();
    message = "view reset";
    return 1;
  }
  return static_cast<int>(interact::applyAction(binding->action, scene_, message));
}

void WebSession::resetView() {
  scene_.render.camera = dragStart_ = loadedCamera_;
}

std::string WebSession::sceneText() const {
  return saveScene(scene_);
}

namespace {

// One schema key's range and current value in `scene`, as the page shows it.
Setting settingOf(const scene_detail::KeySpec& spec, Scene& scene, std::string key) {
  using namespace scene_detail;
  Setting s;
  s.key = std::move(key);
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

std::vector<Setting> WebSession::settings() const {
  std::vector<Setting> out;
  Scene scene = scene_;  // the schema's fields address a mutable Scene
  for (const scene_detail::KeySpec& spec : scene_detail::keySpecs()) {
    if (spec.legacyLight >= 0) continue;  // old names, read only
    out.push_back(settingOf(spec, scene, std::string(spec.name)));
  }
  return out;
}

std::vector<std::vector<Setting>> WebSession::listEntries(std::string_view name) const {
  std::vector<std::vector<Setting>> out;
  const scene_detail::ListSpec* list = scene_detail::findList(name);
  if (!list) return out;
  for (std::size_t i = 0; i < list->size(scene_); ++i) {
    // The entry keys address the first element of a scene whose list holds just this one.
    Scene scratch;
    list->entry(scene_, i, scratch);
    std::vector<Setting> entry;
    for (const scene_detail::KeySpec& spec : list->keys) {
      entry.push_back(settingOf(spec, scratch,
                                std::string(list->name) + "." + std::to_string(i + 1) + "." +
                                    std::string(spec.name)));
    }
    out.push_back(std::move(entry));
  }
  return out;
}

std::vector<std::pair<std::string, double>> WebSession::params() const {
  std::vector<std::pair<std::string, double>> out;
  if (!surface_) return out;
  const auto& names = surface_->formula.graph.params();
  for (std::size_t i = 0; i < names.size() && i < surface_->params.size(); ++i)
    out.emplace_back(names[i], surface_->params[i]);
  return out;
}

std::string WebSession::notes() const {
  std::string notes = importNotes_;
  if (surface_) notes += surface_->methodWarning + surface_->formulaNote + surface_->singularNote;
  return notes;
}

std::string WebSession::method() const {
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

}  // namespace zs::web
