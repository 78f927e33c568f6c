#include "scene/schema.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "scene/scene_io.hpp"

namespace zs::scene_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// What a change invalidates (invalidation.hpp), short for the table's rows.
constexpr Invalidation kFrame = invalidates::Frame;
constexpr Invalidation kVariant = invalidates::Variant;
constexpr Invalidation kShader = invalidates::Shader;
constexpr Invalidation kGeometry = invalidates::Geometry;
constexpr Invalidation kSurface = invalidates::Surface;
constexpr Invalidation kShaderIfSeveral = invalidates::ShaderIfSeveralSurfaces;
constexpr Invalidation kShaderIfMarked = invalidates::ShaderIfMarked;

constexpr Range kAny{-kInf, kInf};
constexpr Range kNonNegative{0, kInf};
constexpr Range kPositive{0, kInf, true};
constexpr Range kUnit{0, 1};

constexpr std::array<std::string_view, 2> kProjections{"perspective", "orthographic"};
constexpr std::array<std::string_view, 2> kCriteria{"thesis", "uniform"};
constexpr std::array<std::string_view, 2> kShapes{"box", "sphere"};  // order of DomainShape
// Order of TracingMethod (render/settings.hpp).
constexpr std::array<std::string_view, 4> kMethods{"auto", "bernstein", "sampling", "interval"};
constexpr std::array<std::string_view, 2> kLightKinds{"directional", "point"};  // LightKind
constexpr std::array<std::string_view, 2> kLightSpaces{"world", "camera"};      // LightSpace
constexpr std::array<std::string_view, 4> kColorModes{"material", "gauss", "mean", "normal"};
constexpr std::array<std::string_view, 2> kRenderModes{"surface", "volume"};  // RenderMode

// A reference to one Scene member, as a plain function pointer the schema can hold.
#define ZS_FIELD(member) +[](Scene& s) -> decltype(auto) { return (s.member); }

const EnumRef kProjectionRef{
    [](const Scene& s) { return static_cast<int>(s.render.camera.projection); },
    [](Scene& s, int v) { s.render.camera.projection = static_cast<Projection>(v); }, kProjections};
const EnumRef kCriteriaRef{[](const Scene& s) { return static_cast<int>(s.octree.criteria); },
                           [](Scene& s, int v) { s.octree.criteria = static_cast<Criteria>(v); },
                           kCriteria};
const EnumRef kShapeRef{[](const Scene& s) { return static_cast<int>(s.domain.shape); },
                        [](Scene& s, int v) { s.domain.shape = static_cast<DomainShape>(v); },
                        kShapes};
const EnumRef kMethodRef{
    [](const Scene& s) { return static_cast<int>(s.render.tracing.method); },
    [](Scene& s, int v) { s.render.tracing.method = static_cast<TracingMethod>(v); }, kMethods};

const EnumRef kColorModeRef{
    [](const Scene& s) { return static_cast<int>(s.render.shading.color); },
    [](Scene& s, int v) { s.render.shading.color = static_cast<ColorMode>(v); }, kColorModes};
const EnumRef kRenderModeRef{[](const Scene& s) { return static_cast<int>(s.render.mode); },
                             [](Scene& s, int v) { s.render.mode = static_cast<RenderMode>(v); },
                             kRenderModes};
const EnumRef kLightSpaceRef{
    [](const Scene& s) { return static_cast<int>(s.render.lights.space); },
    [](Scene& s, int v) { s.render.lights.space = static_cast<LightSpace>(v); }, kLightSpaces};
const EnumRef kLightKindRef{
    [](const Scene& s) { return static_cast<int>(s.render.lights.sources.front().kind); },
    [](Scene& s, int v) { s.render.lights.sources.front().kind = static_cast<LightKind>(v); },
    kLightKinds};

// File order: top-level keys first (TOML puts them before any [table]), then each table's
// keys together, so the writer can emit a header whenever the prefix changes.
const KeySpec kKeys[] = {
    {"opacity", kVariant, ZS_FIELD(render.opacity), {0, 1, true}},
    {"samples", kVariant, ZS_FIELD(render.samples), {1, 8}},
    {"background", kFrame, ZS_FIELD(render.background), kUnit},
    {"surface.level", kSurface, ZS_FIELD(level), kAny},
    {"image.width", kFrame, ZS_FIELD(width), {1, 16384}},
    {"image.height", kFrame, ZS_FIELD(height), {1, 16384}},
    {"domain.min", kGeometry | kShaderIfMarked, ZS_FIELD(domain.min), kAny},
    {"domain.max", kGeometry | kShaderIfMarked, ZS_FIELD(domain.max), kAny},
    {"domain.shape", kGeometry | kShaderIfMarked, kShapeRef, kAny},
    {"domain.center", kGeometry | kShaderIfMarked, ZS_FIELD(domain.center), kAny},
    {"domain.radius", kGeometry | kShaderIfMarked, ZS_FIELD(domain.radius), kPositive},
    {"camera.eye", kFrame, ZS_FIELD(render.camera.eye), kAny},
    {"camera.target", kFrame, ZS_FIELD(render.camera.target), kAny},
    {"camera.up", kFrame, ZS_FIELD(render.camera.up), kAny, true},
    {"camera.projection", kFrame, kProjectionRef, kAny},
    {"camera.fov_y", kFrame, ZS_FIELD(render.camera.fovY), {0, 180, true, true}},
    {"camera.height", kFrame, ZS_FIELD(render.camera.height), kPositive},
    {"octree.level", kGeometry, ZS_FIELD(octree.level), {0, 12}},
    {"octree.criteria", kGeometry, kCriteriaRef, kAny},
    {"octree.node_budget", kGeometry, ZS_FIELD(octree.nodeBudget), {1, 1e9}},
    {"tracing.method", kSurface, kMethodRef, kAny},
    {"tracing.intervals", kFrame, ZS_FIELD(render.tracing.intervals), {1, 1000}},
    {"tracing.epsilon", kFrame, ZS_FIELD(render.tracing.epsilon), kPositive},
    {"tracing.hits", kVariant, ZS_FIELD(render.tracing.hits), {1, 16}},
    {"tracing.max_bisections", kFrame, ZS_FIELD(render.tracing.maxBisections), {1, 200}},
    {"lights.ambient", kFrame | kShaderIfSeveral, ZS_FIELD(render.lights.ambient), kUnit},
    {"lights.space", kVariant, kLightSpaceRef, kAny},
    // The thesis' two lights under their old names: sources[0] and [1] (reader.cpp checks
    // that they are still a directional and a point light first). Read, never written.
    {"lights.directional.direction", kVariant, ZS_FIELD(render.lights.sources[0].direction), kAny,
     true, 0},
    {"lights.directional.intensity", kVariant, ZS_FIELD(render.lights.sources[0].intensity),
     kNonNegative, false, 0},
    {"lights.directional.color", kVariant, ZS_FIELD(render.lights.sources[0].color), kUnit, false,
     0},
    {"lights.point.position", kVariant, ZS_FIELD(render.lights.sources[1].position), kAny, false,
     1},
    {"lights.point.intensity", kVariant, ZS_FIELD(render.lights.sources[1].intensity), kNonNegative,
     false, 1},
    {"lights.point.color", kVariant, ZS_FIELD(render.lights.sources[1].color), kUnit, false, 1},
    {"materials.front.color", kFrame | kShaderIfSeveral, ZS_FIELD(render.materials.front.color),
     kUnit},
    {"materials.front.ambient", kFrame | kShaderIfSeveral, ZS_FIELD(render.materials.front.ambient),
     kUnit},
    {"materials.front.diffuse", kFrame | kShaderIfSeveral, ZS_FIELD(render.materials.front.diffuse),
     kUnit},
    {"materials.front.specular", kFrame | kShaderIfSeveral,
     ZS_FIELD(render.materials.front.specular), kUnit},
    {"materials.front.shininess",
     kFrame | kShaderIfSeveral,
     ZS_FIELD(render.materials.front.shininess),
     {0, 10000}},
    {"materials.back.color", kFrame | kShaderIfSeveral, ZS_FIELD(render.materials.back.color),
     kUnit},
    {"materials.back.ambient", kFrame | kShaderIfSeveral, ZS_FIELD(render.materials.back.ambient),
     kUnit},
    {"materials.back.diffuse", kFrame | kShaderIfSeveral, ZS_FIELD(render.materials.back.diffuse),
     kUnit},
    {"materials.back.specular", kFrame | kShaderIfSeveral, ZS_FIELD(render.materials.back.specular),
     kUnit},
    {"materials.back.shininess",
     kFrame | kShaderIfSeveral,
     ZS_FIELD(render.materials.back.shininess),
     {0, 10000}},
    {"shading.color", kVariant | kShader, kColorModeRef, kAny},
    {"shading.curvature_range", kFrame, ZS_FIELD(render.shading.curvatureRange), kNonNegative},
    {"shading.shadows", kVariant, ZS_FIELD(render.shading.shadows), kAny},
    {"shading.contours.enabled", kShader, ZS_FIELD(render.shading.contours.enabled), kAny},
    {"shading.contours.function", kShader, ZS_FIELD(render.shading.contours.function), kAny},
    {"shading.contours.spacing", kFrame, ZS_FIELD(render.shading.contours.spacing), kPositive},
    {"shading.contours.width", kFrame, ZS_FIELD(render.shading.contours.width), kNonNegative},
    {"shading.contours.color", kFrame, ZS_FIELD(render.shading.contours.color), kUnit},
    {"highlights.silhouette.enabled", kFrame, ZS_FIELD(render.silhouette.enabled), kAny},
    {"highlights.silhouette.threshold", kFrame, ZS_FIELD(render.silhouette.threshold), kUnit},
    {"highlights.silhouette.color", kFrame, ZS_FIELD(render.silhouette.color), kUnit},
    {"highlights.border.enabled", kFrame, ZS_FIELD(render.border.enabled), kAny},
    {"highlights.border.tolerance", kFrame, ZS_FIELD(render.border.threshold), kNonNegative},
    {"highlights.border.color", kFrame, ZS_FIELD(render.border.color), kUnit},
    {"highlights.cut.enabled", kFrame, ZS_FIELD(render.cut.enabled), kAny},
    {"highlights.cut.tolerance", kFrame, ZS_FIELD(render.cut.threshold), kNonNegative},
    {"highlights.cut.color", kFrame, ZS_FIELD(render.cut.color), kUnit},
    {"highlights.intersection.enabled", kFrame | kShaderIfSeveral,
     ZS_FIELD(render.intersection.enabled), kAny},
    {"highlights.intersection.tolerance", kFrame | kShaderIfSeveral,
     ZS_FIELD(render.intersection.threshold), kNonNegative},
    {"highlights.intersection.color", kFrame | kShaderIfSeveral,
     ZS_FIELD(render.intersection.color), kUnit},
    {"highlights.singular.enabled", kShader, ZS_FIELD(render.singular.enabled), kAny},
    {"highlights.singular.radius", kShader, ZS_FIELD(render.singular.threshold), kPositive},
    {"highlights.singular.color", kShader, ZS_FIELD(render.singular.color), kUnit},
    {"reflection.enabled", kVariant, ZS_FIELD(render.reflection.enabled), kAny},
    {"reflection.primary_weight", kFrame, ZS_FIELD(render.reflection.primaryWeight), kUnit},
    {"render.mode", kVariant | kSurface, kRenderModeRef, kAny},
    {"volume.density", kFrame, ZS_FIELD(render.volume.density), kNonNegative},
    {"volume.falloff", kFrame, ZS_FIELD(render.volume.falloff), kPositive},
    {"volume.range", kFrame, ZS_FIELD(render.volume.range), kPositive},
    {"volume.steps", kFrame, ZS_FIELD(render.volume.steps), {1, 4096}},
};

// One [[lights.source]] entry; the fields address the first light of a scene that holds
// just that light (schema.hpp).
const KeySpec kLightKeys[] = {
    {"kind", kVariant, kLightKindRef, kAny},
    {"enabled", kVariant, ZS_FIELD(render.lights.sources.front().enabled), kAny},
    {"direction", kVariant, ZS_FIELD(render.lights.sources.front().direction), kAny, true},
    {"position", kVariant, ZS_FIELD(render.lights.sources.front().position), kAny},
    {"intensity", kVariant, ZS_FIELD(render.lights.sources.front().intensity), kNonNegative},
    {"color", kVariant, ZS_FIELD(render.lights.sources.front().color), kUnit},
};

// One [[clip.plane]] entry, addressing the first plane as the light keys do.
const KeySpec kClipPlaneKeys[] = {
    {"enabled", kVariant, ZS_FIELD(render.clipPlanes.front().enabled), kAny},
    {"normal", kVariant, ZS_FIELD(render.clipPlanes.front().normal), kAny, true},
    {"offset", kFrame, ZS_FIELD(render.clipPlanes.front().offset), kAny},
};

// One [[surface]] entry, addressing the first of Scene::moreSurfaces as the light keys do
// (the list's entry() and store() map entry 1 to the scene's own formula and materials).
#define ZS_SURFACE(member) ZS_FIELD(moreSurfaces.front().member)
const KeySpec kSurfaceKeys[] = {
    {"formula", kSurface, ZS_SURFACE(formula), kAny, false, -1, true},
    {"level", kSurface, ZS_SURFACE(level), kAny},
    {"front.color", kFrame | kShaderIfSeveral, ZS_SURFACE(materials.front.color), kUnit},
    {"front.ambient", kFrame | kShaderIfSeveral, ZS_SURFACE(materials.front.ambient), kUnit},
    {"front.diffuse", kFrame | kShaderIfSeveral, ZS_SURFACE(materials.front.diffuse), kUnit},
    {"front.specular", kFrame | kShaderIfSeveral, ZS_SURFACE(materials.front.specular), kUnit},
    {"front.shininess",
     kFrame | kShaderIfSeveral,
     ZS_SURFACE(materials.front.shininess),
     {0, 10000}},
    {"back.color", kFrame | kShaderIfSeveral, ZS_SURFACE(materials.back.color), kUnit},
    {"back.ambient", kFrame | kShaderIfSeveral, ZS_SURFACE(materials.back.ambient), kUnit},
    {"back.diffuse", kFrame | kShaderIfSeveral, ZS_SURFACE(materials.back.diffuse), kUnit},
    {"back.specular", kFrame | kShaderIfSeveral, ZS_SURFACE(materials.back.specular), kUnit},
    {"back.shininess", kFrame | kShaderIfSeveral, ZS_SURFACE(materials.back.shininess), {0, 10000}},
};
#undef ZS_SURFACE

#undef ZS_FIELD

const ListSpec kLists[] = {
    {kLightSourcesKey, "light", kLightKeys, static_cast<std::size_t>(kMaxLights),
     "{ kind = \"point\", position = [0, 0, 5] }",
     "switch lights off with enabled = false rather than adding more",
     [](const Scene& s) { return s.render.lights.sources.size(); },
     [](Scene& s, std::size_t n) { s.render.lights.sources.resize(n); },
     [](const Scene& from, std::size_t i, Scene& scratch) {
       scratch.render.lights.sources = {from.render.lights.sources[i]};
     },
     [](const Scene& scratch, Scene& to, std::size_t i) {
       to.render.lights.sources[i] = scratch.render.lights.sources.front();
     },
     "lights.space"},
    {kClipPlanesKey, "clip plane", kClipPlaneKeys, static_cast<std::size_t>(kMaxClipPlanes),
     "{ normal = [0, 0, 1], offset = 0.5 }",
     "switch planes off with enabled = false, or combine the cuts you need in fewer planes",
     [](const Scene& s) { return s.render.clipPlanes.size(); },
     [](Scene& s, std::size_t n) { s.render.clipPlanes.resize(n); },
     [](const Scene& from, std::size_t i, Scene& scratch) {
       scratch.render.clipPlanes = {from.render.clipPlanes[i]};
     },
     [](const Scene& scratch, Scene& to, std::size_t i) {
       to.render.clipPlanes[i] = scratch.render.clipPlanes.front();
     },
     ""},
    {kSurfacesKey, "surface", kSurfaceKeys, static_cast<std::size_t>(kMaxSurfaces),
     "{ formula = \"x^2 + y^2 + z^2 - 1\" }",
     "combine surfaces into one formula (a product F*G draws both) or drop one",
     [](const Scene& s) { return 1 + s.moreSurfaces.size(); },
     [](Scene& s, std::size_t n) {
       const std::size_t old = 1 + s.moreSurfaces.size();
       s.moreSurfaces.resize(n > 0 ? n - 1 : 0);
       for (std::size_t i = std::max<std::size_t>(old, 1); i < n; ++i)
         s.moreSurfaces[i - 1].materials = surfaceMaterials(i);
     },
     [](const Scene& from, std::size_t i, Scene& scratch) {
       scratch.moreSurfaces = {surfaceAt(from, i)};
     },
     [](const Scene& scratch, Scene& to, std::size_t i) {
       const SurfaceEntry& e = scratch.moreSurfaces.front();
       if (i > 0) {
         to.moreSurfaces[i - 1] = e;
         return;
       }
       to.formula = e.formula;
       to.level = e.level;
       to.render.materials = e.materials;
     },
     "", "formula",
     [](Scene& scratch, std::size_t i) {
       scratch.moreSurfaces = {SurfaceEntry{}};
       scratch.moreSurfaces.front().materials = surfaceMaterials(i);
     }},
};

}  // namespace

std::span<const KeySpec> keySpecs() {
  return kKeys;
}

std::span<const ListSpec> listSpecs() {
  return kLists;
}

const ListSpec* findList(std::string_view dottedName) {
  for (const ListSpec& l : kLists) {
    if (l.name == dottedName) return &l;
  }
  return nullptr;
}

std::span<const KeySpec> lightKeySpecs() {
  return kLightKeys;
}

const KeySpec* findListKey(const ListSpec& list, std::string_view name) {
  for (const KeySpec& k : list.keys) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

const KeySpec* findKey(std::string_view dottedName) {
  for (const KeySpec& k : kKeys) {
    if (k.name == dottedName) return &k;
  }
  return nullptr;
}

bool describesFirstSurface(std::string_view dottedName) {
  return dottedName == kFormulaKey || dottedName == "surface.level" ||
         dottedName.starts_with("materials.");
}

bool isTableName(std::string_view dottedName) {
  if (dottedName == kParamsKey) return true;
  for (const ListSpec& l : kLists) {
    if (l.name == dottedName || l.name.starts_with(std::string(dottedName) + ".")) return true;
  }
  return std::any_of(std::begin(kKeys), std::end(kKeys), [&](const KeySpec& k) {
    return k.name.size() > dottedName.size() && k.name.starts_with(dottedName) &&
           k.name[dottedName.size()] == '.';
  });
}

}  // namespace zs::scene_detail
