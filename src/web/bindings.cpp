// The web page's window into the core (embind): the session's methods, with the hierarchy's
// texels as a Uint32Array and a frame's uniforms as plain objects, so that web/*.js only
// wires controls and hands numbers to WebGL2.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "i18n/translate.hpp"
#include "interact/formula_keyboard.hpp"
#include "interact/kiosk.hpp"
#include "interact/parameter_range.hpp"
#include "interact/trace_budget.hpp"
#include "session/session.hpp"

using emscripten::val;

namespace zs::web {
namespace {

using WebSession = session::Session;
using session::Setting;

// The page's session: GLSL ES 3.00 for WebGL2, which compiles and reports what it rejects.
WebSession* makeWebSession() {
  return new WebSession(session::SessionOptions{ShaderDialect::Es300, false});
}

// A JS typed array holding a copy of `values` (a view into wasm memory would be invalidated
// when the heap grows): Uint32Array or Float32Array after the element type.
template <class T>
val typedArrayCopy(const char* type, const std::vector<T>& values) {
  val array = val::global(type).new_(values.size());
  array.call<void>("set", val(emscripten::typed_memory_view(values.size(), values.data())));
  return array;
}

// A plain JS array of `items`, each converted by `convert` (the values themselves by default).
template <class Range, class Convert>
val arrayOf(const Range& items, Convert convert) {
  val out = val::array();
  for (const auto& item : items) out.call<void>("push", convert(item));
  return out;
}
template <class Range>
val arrayOf(const Range& items) {
  return arrayOf(items, [](const auto& item) { return item; });
}

std::string applyOverridesJs(WebSession& s, val assignments) {
  std::vector<std::string> list;
  const int n = assignments["length"].as<int>();
  for (int i = 0; i < n; ++i) list.push_back(assignments[i].as<std::string>());
  return s.applyOverrides(list);
}

val hierarchyOf(const GpuHierarchy& h) {
  val out = val::object();
  out.set("texels", typedArrayCopy("Uint32Array", h.texels));
  out.set("count", h.count);
  return out;
}

val hierarchyJs(const WebSession& s) {
  return hierarchyOf(s.hierarchy());
}
val quickHierarchyJs(const WebSession& s) {
  return hierarchyOf(s.quickHierarchy());
}
val interpreterShadersJs(const WebSession& s) {
  return arrayOf(s.interpreterShaders());
}
val quickTapeJs(const WebSession& s) {
  return typedArrayCopy("Uint32Array", s.quickTape());
}

const char* kindName(UniformValue::Kind kind) {
  switch (kind) {
    case UniformValue::Kind::Int:
      return "int";
    case UniformValue::Kind::Float:
      return "float";
    case UniformValue::Kind::Vec2:
      return "vec2";
    case UniformValue::Kind::Vec3:
      return "vec3";
    case UniformValue::Kind::Vec4:
      return "vec4";
    case UniformValue::Kind::Mat4:
      return "mat4";
    case UniformValue::Kind::FloatArray:
      return "floats";
  }
  return "float";
}

val frameOf(const WebSession& s, const FrameUniforms& frame) {
  val out = val::object();
  out.set("uniforms", arrayOf(frame.values, [](const UniformValue& u) {
            val entry = val::object();
            entry.set("name", u.name);
            entry.set("kind", std::string(kindName(u.kind)));
            if (u.kind == UniformValue::Kind::Int)
              entry.set("value", u.integer);
            else
              entry.set("value", typedArrayCopy("Float32Array", u.values));
            return entry;
          }));
  out.set("vertices", frame.vertices);
  out.set("background", arrayOf(s.scene().render.background));
  return out;
}

val frameJs(const WebSession& s, int width, int height) {
  return frameOf(s, s.frame(width, height));
}
val quickFrameJs(const WebSession& s, int width, int height) {
  return frameOf(s, s.quickFrame(width, height));
}

val paramsJs(const WebSession& s) {
  return arrayOf(s.params(), [](const std::pair<std::string, double>& param) {
    val p = val::object();
    p.set("name", param.first);
    p.set("value", param.second);
    const auto [lo, hi] = interact::paramRange(param.second);
    p.set("lo", lo);
    p.set("hi", hi);
    return p;
  });
}

// The viewer's actions that are the page's own (not scene edits), by the name app.js
// handles; "" for those the page has no use for (mesh export, print, quit).
const char* pageAction(interact::Action action) {
  using interact::Action;
  switch (action) {
    case Action::NextExample:
      return "next";
    case Action::PrevExample:
      return "previous";
    case Action::Screenshot:
    case Action::WindowShot:
      return "png";
    case Action::SaveScene:
      return "save";
    case Action::FocusFormula:
      return "formula";
    case Action::TogglePanel:
      return "panel";
    case Action::ToggleGallery:
      return "gallery";
    case Action::ResetView:
      return "reset";
    default:
      return "";
  }
}

val keyJs(WebSession& s, int keyCode, int mods) {
  std::string message;
  const int effect = s.key(keyCode, mods, message);
  val out = val::object();
  out.set("effect", effect);
  out.set("message", message);
  const interact::KeyBinding* binding = interact::findBinding(keyCode, mods);
  out.set("action", std::string(binding ? pageAction(binding->action) : ""));
  return out;
}

// The key table for the page's list of keys: the bindings the page acts on.
val keysJs() {
  val out = val::array();
  for (const interact::KeyBinding& b : interact::keyBindings()) {
    if (b.action == interact::Action::ExportMesh || b.action == interact::Action::PrintPage ||
        b.action == interact::Action::Quit)
      continue;
    val k = val::object();
    k.set("key", std::string(b.keyName));
    k.set("description", std::string(b.description));
    k.set("kiosk", interact::kioskAllows(b.action));
    out.call<void>("push", k);
  }
  return out;
}

val settingJs(const Setting& setting) {
  val e = val::object();
  e.set("key", setting.key);
  e.set("type", setting.type);
  e.set("lo", setting.lo);
  e.set("hi", setting.hi);
  e.set("loOpen", setting.loOpen);
  e.set("hiOpen", setting.hiOpen);
  e.set("choices", arrayOf(setting.choices));
  e.set("value", arrayOf(setting.value));
  e.set("choice", setting.choice);
  e.set("group", setting.group);
  return e;
}

val settingsJs(const WebSession& s) {
  return arrayOf(s.settings(), settingJs);
}

val listEntriesJs(const WebSession& s, const std::string& list) {
  return arrayOf(s.listEntries(list),
                 [](const std::vector<Setting>& entry) { return arrayOf(entry, settingJs); });
}

val probeJs(const WebSession& s, int x, int y, int width, int height) {
  auto result = s.probe(x, y, width, height);
  val out = val::object();
  if (auto* err = std::get_if<std::string>(&result)) {
    out.set("error", *err);
    return out;
  }
  const ProbeResult& r = std::get<ProbeResult>(result);
  out.set("hit", r.hit);
  if (!r.hit) return out;
  out.set("point", arrayOf(r.point));
  out.set("F", r.value);
  out.set("gradient", arrayOf(r.gradient));
  out.set("normal", arrayOf(r.normal));
  out.set("K", r.gaussian);
  out.set("H", r.mean);
  out.set("k1", r.k1);
  out.set("k2", r.k2);
  out.set("surface", r.surface + 1);  // counted from 1, as the panel names them
  out.set("surfaces", r.surfaces);
  return out;
}

std::string formulaJs(const WebSession& s) {
  return s.scene().formula;
}

// Kiosk mode (interact/kiosk.hpp, interact/formula_keyboard.hpp): the page's defaults are
// the viewer's.
val kioskDefaultsJs() {
  const interact::KioskPolicy policy;
  val out = val::object();
  out.set("idleSeconds", policy.idleSeconds);
  out.set("maxDegree", policy.maxDegree);
  return out;
}

std::string kioskRefusalJs(const std::string& formula, int maxDegree) {
  interact::KioskPolicy policy;
  policy.maxDegree = maxDegree;
  return interact::kioskRefusal(formula, policy);
}

// The divisor of each side for a picture while dragging, from the cost per pixel of the
// last one: the viewer's rule (interact/trace_budget.hpp). A first picture's is the
// session's quickScale.
int dragScaleJs(double msPerPixel, int width, int height) {
  return interact::dragScale(msPerPixel, width, height);
}

val formulaKeyRowsJs() {
  return arrayOf(interact::formulaKeyRows(), [](const auto& row) {
    return arrayOf(row, [](std::string_view key) { return val(std::string(key)); });
  });
}

std::string pressFormulaKeyJs(const std::string& text, const std::string& key) {
  return interact::pressFormulaKey(text, key);
}

// The page's language (i18n/translate.hpp): the same catalogs as the viewer's; the core's
// own messages (kiosk refusals, key effects) follow it too.
val languagesJs() {
  return arrayOf(i18n::languages(), [](const i18n::Language& l) {
    val out = val::object();
    out.set("code", std::string(l.code));
    out.set("name", std::string(l.name));
    return out;
  });
}

std::string translateJs(const std::string& text) {
  return i18n::tr(text);
}
bool setLanguageJs(const std::string& tag) {
  return i18n::setLanguage(tag);
}
std::string currentLanguageJs() {
  return std::string(i18n::currentLanguage());
}
std::string knownLanguageJs(const std::string& tag) {
  return i18n::knownLanguage(tag);
}

}  // namespace

EMSCRIPTEN_BINDINGS(zeroset) {
  emscripten::function("keys", &keysJs);
  emscripten::function(
      "typingPauseMs", +[] { return session::kTypingPauseMs; });
  emscripten::function(
      "panelGroups", +[] {
        val out = val::array();
        for (std::string_view g : session::panelGroups()) out.call<void>("push", std::string(g));
        return out;
      });
  emscripten::function(
      "panelGroup", +[](const std::string& key) { return std::string(session::panelGroup(key)); });
  emscripten::function("dragScale", &dragScaleJs);
  emscripten::function("kioskDefaults", &kioskDefaultsJs);
  emscripten::function("kioskRefusal", &kioskRefusalJs);
  emscripten::function("formulaKeyRows", &formulaKeyRowsJs);
  emscripten::function("pressFormulaKey", &pressFormulaKeyJs);
  emscripten::function("languages", &languagesJs);
  emscripten::function("translate", &translateJs);
  emscripten::function("setLanguage", &setLanguageJs);
  emscripten::function("currentLanguage", &currentLanguageJs);
  emscripten::function("knownLanguage", &knownLanguageJs);
  emscripten::class_<WebSession>("Session")
      .constructor(&makeWebSession, emscripten::allow_raw_pointers())
      // embind passes std::string, not std::string_view
      .function("loadFormula",
                emscripten::optional_override(
                    [](WebSession& s, const std::string& f) { return s.loadFormula(f); }))
      .function("setFormula",
                emscripten::optional_override(
                    [](WebSession& s, const std::string& f) { return s.setFormula(f); }))
      .function("addSurface",
                emscripten::optional_override(
                    [](WebSession& s, const std::string& f) { return s.addSurface(f); }))
      .function("loadSurf", emscripten::optional_override(
                                [](WebSession& s, const std::string& text,
                                   const std::string& name) { return s.loadSurf(text, name); }))
      .function("loadJsurf", emscripten::optional_override(
                                 [](WebSession& s, const std::string& text,
                                    const std::string& name) { return s.loadJsurf(text, name); }))
      .function("loadSurfScript",
                emscripten::optional_override(
                    [](WebSession& s, const std::string& text, const std::string& name) {
                      return s.loadSurfScript(text, name);
                    }))
      .function("applyOverrides", &applyOverridesJs)
      .function("setParam",
                emscripten::optional_override([](WebSession& s, const std::string& name,
                                                 double value) { return s.setParam(name, value); }))
      .function("prepare", &session::Session::prepare)
      .function("prepared", &session::Session::prepared)
      .function("generation", &session::Session::generation)
      .function("vertexShader", &session::Session::vertexShader)
      .function("fragmentShader", &session::Session::fragmentShader)
      .function("hierarchy", &hierarchyJs)
      .function("frame", &frameJs)
      .function("prepareQuick",
                emscripten::optional_override([](WebSession& s) { return s.prepareQuick(); }))
      .function("quickPrepared", &session::Session::quickPrepared)
      .function("quickPolynomialOnly", &session::Session::quickPolynomialOnly)
      .function("quickFragmentShader", &session::Session::quickFragmentShader)
      .function("quickScale", &session::Session::quickScale)
      .function("quickDrawn", &session::Session::quickDrawn)
      .function("quickTape", &quickTapeJs)
      .function("interpreterShaders", &interpreterShadersJs)
      .function("quickHierarchy", &quickHierarchyJs)
      .function("quickFrame", &quickFrameJs)
      .function("beginDrag", &session::Session::beginDrag)
      .function("drag", &session::Session::drag)
      .function("zoom", &session::Session::zoom)
      .function("key", &keyJs)
      .function("resetView", &session::Session::resetView)
      .function("sceneText", &session::Session::sceneText)
      .function("formula", &formulaJs)
      .function("probe", &probeJs)
      .function("params", &paramsJs)
      .function("settings", &settingsJs)
      .function("listEntries", &listEntriesJs)
      .function("notes", &session::Session::notes)
      .function("method", &session::Session::method);
}

}  // namespace zs::web
