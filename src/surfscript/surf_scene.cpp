#include "surfscript/surf_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "expr/number_text.hpp"

namespace zs::surfscript {

namespace {

Vec3 mapPoint(const AffineMap& m, const Vec3& s) {
  Vec3 out{};
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * s[0] + m[i][1] * s[1] + m[i][2] * s[2] + m[i][3];
  return out;
}

Vec3 column(const AffineMap& m, int j) {
  return {m[0][j], m[1][j], m[2][j]};
}

double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec3 scaled(const Vec3& v, double k) {
  return {v[0] * k, v[1] * k, v[2] * k};
}

Vec3 plus(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

// The uniform scale k of a map whose linear part is k times a rotation, or 0 when it is not
// one (a non-uniform scale_*, a mirror).
double similarityScale(const AffineMap& m) {
  const Vec3 c[3] = {column(m, 0), column(m, 1), column(m, 2)};
  const double k2 = dot(c[0], c[0]);
  if (!(k2 > 0) || !std::isfinite(k2)) return 0;
  constexpr double tol = 1e-9;
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      const double want = i == j ? k2 : 0;
      if (std::abs(dot(c[i], c[j]) - want) > tol * k2) return 0;
    }
  }
  const Vec3 cross{c[0][1] * c[1][2] - c[0][2] * c[1][1], c[0][2] * c[1][0] - c[0][0] * c[1][2],
                   c[0][0] * c[1][1] - c[0][1] * c[1][0]};
  if (dot(cross, c[2]) <= 0) return 0;
  return std::sqrt(k2);
}

AffineMap translation(double ox, double oy, double oz) {
  AffineMap m = identityMap();
  m[0][3] = -ox;
  m[1][3] = -oy;
  m[2][3] = -oz;
  return m;
}

AffineMap scaling(double sx, double sy, double sz) {
  AffineMap m = identityMap();
  m[0][0] = sx;
  m[1][1] = sy;
  m[2][2] = sz;
  return m;
}

// surf's camera chain at draw time (draw/SurfaceCalc: the surface's polynomial p becomes
// p o chain): translate by the origin, turn (y, then x, then z), scale, in the order that
// first, second and third give (translate 0, rotate 1, scale 2). The map takes a screen
// point to the model point drawn there.
AffineMap cameraChain(const Globals& g) {
  const AffineMap steps[3] = {
      translation(g.number("origin_x"), g.number("origin_y"), g.number("origin_z")),
      compose(compose(surfRotation(g.number("rot_y"), 1), surfRotation(g.number("rot_x"), 0)),
              surfRotation(g.number("rot_z"), 2)),
      scaling(g.number("scale_x"), g.number("scale_y"), g.number("scale_z")),
  };
  AffineMap chain = identityMap();
  bool used[3] = {false, false, false};
  for (const char* slot : {"first", "second", "third"}) {
    const int step = g.integer(slot);
    if (step < 0 || step > 2 || used[step]) continue;
    used[step] = true;
    chain = compose(chain, steps[step]);
  }
  for (int step = 0; step < 3; ++step)
    if (!used[step]) chain = compose(chain, steps[step]);
  return chain;
}

// Values beyond what a scene holds (a colour over 255, a weight over 100) are drawn at the
// nearest one it does; the first such key is named in a note.
struct Clamp {
  std::string first;  // the first key clamped, "" when none
  double operator()(double v, double lo, double hi, const std::string& key) {
    const double c = std::isfinite(v) ? std::clamp(v, lo, hi) : lo;
    if (c != v && first.empty()) first = key;
    return c;
  }
};

Vec3 rgb(const Globals& g, const std::string& prefix, Clamp& within) {
  return {within(g.number(prefix + "_red") / 255, 0, 1, prefix + "_red"),
          within(g.number(prefix + "_green") / 255, 0, 1, prefix + "_green"),
          within(g.number(prefix + "_blue") / 255, 0, 1, prefix + "_blue")};
}

std::string suffix(int surface) {
  return surface == 1 ? "" : std::to_string(surface);
}

// surf's weights for surface `i` (1-based) as a zeroset material. surf's highlight is
// Blinn's (N.H)^n, zeroset's Phong's (R.V)^m, which is about the same lobe for m = n / 4.
Material material(const Globals& g, int i, bool front, Clamp& within) {
  const std::string k = suffix(i);
  const int flags = g.integer("illumination");
  Material m;
  m.color = rgb(g, (front ? "surface" : "inside") + k, within);
  m.ambient = 1;  // lights.ambient carries surface 1's `ambient`, which surf uses for all
  m.diffuse = (flags & 2) ? within(g.number("diffuse" + k) / 100, 0, 1, "diffuse" + k) : 0;
  m.specular = (flags & 4) ? within(g.number("reflected" + k) / 100, 0, 1, "reflected" + k) : 0;
  m.shininess = within(g.number("smoothness" + k) / 4, 1, 10000, "smoothness" + k);
  return m;
}

struct ScreenMap {
  AffineMap screenToWorld;  // a similarity: k times a rotation, plus a translation
  double k = 1;
};

Camera cameraOf(const Globals& g, const ScreenMap& f, int width, int height) {
  const double hf = width >= height ? 10 : 10.0 * height / width;
  // surf samples pixel centres from -hf to hf: the picture's edges lie half a pixel beyond.
  const double halfHeight = hf * height / std::max(1, height - 1);
  const Vec3 target = mapPoint(f.screenToWorld, {0, 0, 0});
  const Vec3 up = scaled(column(f.screenToWorld, 1), 1 / f.k);
  const Vec3 back = scaled(column(f.screenToWorld, 2), 1 / f.k);
  Camera cam;
  cam.target = target;
  cam.up = up;
  if (g.integer("perspective") == 1) {
    const double z0 = g.number("spec_z") > 0 ? g.number("spec_z") : 25;
    cam.projection = Projection::Perspective;
    cam.eye = mapPoint(f.screenToWorld, {0, 0, z0});
    cam.fovY = 2 * std::atan(halfHeight / z0) * 180 / M_PI;
  } else {
    cam.projection = Projection::Orthographic;
    cam.eye = plus(target, scaled(back, 40 * f.k));  // beyond surf's depth range of +-10
    cam.height = 2 * halfHeight * f.k;
  }
  return cam;
}

// The screen-space slab surf searches, clip_back <= z <= clip_front, as clip planes where
// the domain reaches beyond it.
void depthPlanes(const Globals& g, const ScreenMap& f, double domainReach, RenderSettings& r) {
  const Vec3 back = scaled(column(f.screenToWorld, 2), 1 / f.k);
  const double front = g.number("clip_front"), rear = g.number("clip_back");
  if (domainReach > front) {
    r.clipPlanes.push_back({true, back, dot(back, mapPoint(f.screenToWorld, {0, 0, front}))});
  }
  if (-domainReach < rear) {
    r.clipPlanes.push_back(
        {true, scaled(back, -1), -dot(back, mapPoint(f.screenToWorld, {0, 0, rear}))});
  }
}

// A clip polynomial a - b*L^2 with L affine (a slab |L| <= sqrt(a/b)), such as SURFER-2008's
// 1 - x^2.
struct Slab {
  Affine form;
  double half = 0;
};

std::optional<Slab> slabOf(const Poly& p) {
  auto s = p.slab();
  if (!s) return std::nullopt;
  return Slab{s->first, s->second};
}

}  // namespace

Scene surfaceScene(const Drawing& d, std::vector<Note>& notes) {
  const Globals& g = d.globals;
  auto say = [&](std::string message) {
    for (const Note& n : notes)
      if (n.message == message) return;
    notes.push_back({d.place, std::move(message)});
  };
  Clamp within;
  Scene scene;
  scene.width = g.integer("width") > 0 ? int(within(g.integer("width"), 1, 16384, "width")) : 200;
  scene.height =
      g.integer("height") > 0 ? int(within(g.integer("height"), 1, 16384, "height")) : 200;

  // The surfaces surf draws: surface, surface2 ... surface9 of degree 1 or more.
  std::vector<std::pair<int, Poly>> surfaces;
  for (int i = 1; i <= 9; ++i) {
    const Poly* p = g.poly("surface" + suffix(i));
    if (p && p->degree() >= 1) surfaces.emplace_back(i, *p);
  }
  if (int(surfaces.size()) > kMaxSurfaces) {
    say("zeroset draws " + std::to_string(kMaxSurfaces) + " surfaces at once: surface" +
        std::to_string(surfaces[kMaxSurfaces].first) + " and after are left out");
    surfaces.erase(surfaces.begin() + kMaxSurfaces, surfaces.end());
  }
  if (surfaces.empty()) {
    scene.formula.clear();
    return scene;
  }

  const AffineMap chain = cameraChain(g);
  const int clip = g.integer("clip");
  const bool modelClip = clip >= 1 && clip <= 6;  // the solids that live in model space
  // The world zeroset draws in: the script's own coordinates where the map from the screen
  // is a similarity (the formula stays as written), else surf's screen itself.
  bool sharedMap = true;
  for (const auto& [i, p] : surfaces)
    sharedMap = sharedMap && p.pending() == surfaces[0].second.pending();
  ScreenMap frame;
  std::vector<std::string> formulas;
  AffineMap toWorld =
      modelClip || !sharedMap ? chain : compose(surfaces[0].second.pending(), chain);
  if (const double k = similarityScale(toWorld); k > 0) {
    frame = {toWorld, k};
    for (const auto& [i, p] : surfaces)
      formulas.push_back(modelClip || !sharedMap ? p.applied().formula() : p.written().formula());
  } else {
    say("the view (scale_x, scale_y, scale_z or a mirror) is not a turn with one scale: the "
        "formula is "
        "written in surf's screen coordinates");
    frame = {identityMap(), 1};
    for (const auto& [i, p] : surfaces) formulas.push_back(p.substitute(chain).formula());
  }
  scene.formula = formulas[0];
  for (std::size_t s = 1; s < surfaces.size(); ++s) {
    SurfaceEntry e;
    e.formula = formulas[s];
    e.materials = {material(g, surfaces[s].first, true, within),
                   material(g, surfaces[s].first, false, within)};
    scene.moreSurfaces.push_back(e);
  }

  RenderSettings& r = scene.render;
  r.camera = cameraOf(g, frame, scene.width, scene.height);
  r.materials = {material(g, surfaces[0].first, true, within),
                 material(g, surfaces[0].first, false, within)};
  r.silhouette.enabled = false;
  r.border.enabled = false;
  r.reflection.enabled = false;
  r.intersection.enabled = false;
  r.samples = std::clamp(g.integer("antialiasing"), 1, 4);
  r.background = g.integer("do_background") == 0 ? rgb(g, "background", within) : Vec3{0, 0, 0};
  const int flags = g.integer("illumination");
  r.lights.ambient = (flags & 1) ? within(g.number("ambient") / 100, 0, 1, "ambient") : 0;
  r.lights.space = LightSpace::World;
  r.lights.sources.clear();
  struct SurfLight {
    Light light;
    double strength;
  };
  std::vector<SurfLight> lights;
  for (int l = 1; l <= 9; ++l) {
    const std::string k = "light" + std::to_string(l);
    const Vec3 color = rgb(g, k, within);
    const double vol = within(g.number(k + "_vol") / 100, 0, 1e6, k + "_vol");
    if (vol <= 0 || color[0] + color[1] + color[2] <= 0) continue;
    Light light;
    light.kind = LightKind::Point;
    light.position =
        mapPoint(frame.screenToWorld, {g.number(k + "_x"), g.number(k + "_y"), g.number(k + "_z")});
    light.intensity = vol;
    light.color = color;
    lights.push_back({light, vol * (color[0] + color[1] + color[2])});
  }
  if (int(lights.size()) > kMaxLights) {
    say("zeroset has " + std::to_string(kMaxLights) + " lights: the dimmest of surf's " +
        std::to_string(lights.size()) + " is left out");
    std::stable_sort(lights.begin(), lights.end(), [](const SurfLight& a, const SurfLight& b) {
      return a.strength > b.strength;
    });
    lights.resize(kMaxLights);
  }
  for (const SurfLight& l : lights) r.lights.sources.push_back(l.light);

  if ((flags & 8) && g.number("transparence") > 0) {
    r.opacity = std::clamp(1 - g.number("transparence") / 100, 0.05, 1.0);
    say("surfaces are see-through with one opacity, " + shortestText(r.opacity) +
        " (surf's thickness, which makes slanting parts more opaque, is not drawn)");
  }
  if (g.integer("depth_cueing") == 0)
    say("surf darkens what lies farther back (depth_cueing, on by default); zeroset shades every "
        "depth alike");
  if (g.integer("stereo_eye") != 0)
    say("surf's stereo pictures (stereo_eye) are not drawn: one view is");

  // The clip solid, as the domain.
  Domain& dom = scene.domain;
  if (clip == 0 || clip > 8 || clip < 0) {
    if (clip != 0)
      say("clip " + std::to_string(clip) + " is not one of surf's: surf clips to its sphere");
    const double radius = g.number("radius") > 0 ? g.number("radius") : 10;
    const Vec3 c{g.number("center_x"), g.number("center_y"), g.number("center_z")};
    dom.shape = DomainShape::Sphere;
    dom.center = mapPoint(frame.screenToWorld, c);
    dom.radius = radius * frame.k;
    depthPlanes(g, frame, std::max(c[2] + radius, radius - c[2]), r);
  } else if (modelClip) {
    const double radius = g.number("radius") > 0 ? g.number("radius") : 10;
    const Vec3 c{g.number("center_x"), g.number("center_y"), g.number("center_z")};
    if (clip != 2)
      say("surf's clip " + std::to_string(clip) +
          " (tetrahedron, octahedron, dodecahedron, icosahedron or cylinder) is drawn within its "
          "bounding cube");
    dom.shape = DomainShape::Box;
    for (int a = 0; a < 3; ++a) {
      dom.min[a] = c[a] - radius;
      dom.max[a] = c[a] + radius;
    }
    depthPlanes(g, frame, radius * std::sqrt(3.0) / frame.k, r);
  } else {
    // none (8) or user (7): the window and the depth slab bound the picture; user's clip
    // polynomials cut it further where they are slabs such as 1 - x^2.
    const double hf = scene.width >= scene.height ? 10 : 10.0 * scene.height / scene.width;
    const double wf = scene.width >= scene.height ? 10.0 * scene.width / scene.height : 10;
    const double depth =
        std::max(std::abs(g.number("clip_front")), std::abs(g.number("clip_back")));
    dom.shape = DomainShape::Sphere;
    dom.center = mapPoint(frame.screenToWorld, {0, 0, 0});
    dom.radius = std::sqrt(wf * wf + hf * hf + depth * depth) * frame.k;
    depthPlanes(g, frame, depth, r);
    if (clip == 7) {
      bool boxed = false;
      Vec3 lo{-1e300, -1e300, -1e300}, hi{1e300, 1e300, 1e300};
      for (int c = 1; c <= 12; ++c) {
        const Poly* p = g.poly(c == 1 ? "clip_surface" : "clip_surface" + std::to_string(c));
        if (!p) continue;
        // In the world's coordinates: the written polynomial where it turns as the surface does.
        const bool sameTurn = sharedMap && p->pending() == surfaces[0].second.pending() &&
                              !modelClip && frame.screenToWorld == toWorld;
        const std::optional<Slab> slab = sameTurn ? slabOf(p->written()) : std::nullopt;
        int axis = -1;
        if (slab && slab->half > 0) {
          int terms = 0;
          for (int a = 0; a < 3; ++a)
            if (slab->form[a] != 0) {
              ++terms;
              axis = a;
            }
          if (terms != 1) axis = -1;
        }
        if (axis >= 0) {
          const double a = slab->form[axis], b = slab->form[3];
          // |a w + b| <= half
          const double w0 = (-slab->half - b) / a, w1 = (slab->half - b) / a;
          lo[axis] = std::max(lo[axis], std::min(w0, w1));
          hi[axis] = std::min(hi[axis], std::max(w0, w1));
          boxed = true;
        } else {
          say("clip_surface" + (c == 1 ? std::string() : std::to_string(c)) +
              " is not a slab such as 1 - x^2: zeroset does not clip with it");
        }
      }
      if (boxed) {
        // The slabs' box, within the ball the window and the depth slab reach.
        dom.shape = DomainShape::Box;
        for (int a = 0; a < 3; ++a) {
          dom.min[a] = std::max(lo[a], dom.center[a] - dom.radius);
          dom.max[a] = std::min(hi[a], dom.center[a] + dom.radius);
        }
      }
    }
  }
  if (dom.shape == DomainShape::Box) {
    bool empty = false;
    for (int a = 0; a < 3; ++a) {
      if (!(dom.min[a] < dom.max[a])) {
        empty = true;
        dom.max[a] = dom.min[a] + 1e-9 * std::max(1.0, std::abs(dom.min[a]));
      }
    }
    if (empty) say("the clip solid leaves nothing inside the window: the picture is empty");
  }
  if (!within.first.empty())
    say(within.first +
        " (or another setting) is beyond what zeroset draws: it is drawn at the nearest value it "
        "can");
  return scene;
}

}  // namespace zs::surfscript
