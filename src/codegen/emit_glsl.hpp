#pragma once
// GLSL for a formula: takes an expression graph with the root of F and the roots of its
// gradient (expr/derivative.hpp), puts out the "formula block" that is spliced between the
// prelude and the ray tracer of the fragment shader (codegen/shader_assembly.hpp):
//
//   uniform float zs_params[K];      // only when the graph has K > 0 parameters
//   float zs_F(vec3 p)     { ... }   // F only: the nodes F needs
//   vec4  zs_FGrad(vec3 p) { ... }   // xyz = gradient, w = F, sharing every temporary
//
// Every non-leaf node becomes one temporary `float tN = <op>(operands);` whose operands are
// other temporaries, p.x/p.y/p.z, zs_params[i] or float literals, so expressions never nest
// and deep formulas cannot exhaust a GLSL compiler's parser. Integer powers are chains of
// multiplications (repeated squaring, squares shared between powers of the same base).
// Points outside F's domain set a flag and make zs_F return zs_UNDEFINED; docs/codegen.md
// has the full contract. Every identifier is generated here, none comes from the formula.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "expr/graph.hpp"

namespace zs {

struct GlslFormula {
  std::string source;           // the formula block, ending with a newline
  std::size_t paramCount = 0;   // K: length of zs_params (== graph.params().size())
  std::size_t temporaries = 0;  // float temporaries declared in zs_FGrad (the larger body)
};

// f and grad must be nodes of g (grad as returned by gradient(g, f)).
GlslFormula emitFormulaGlsl(const Graph& g, NodeId f, const std::array<NodeId, 3>& grad);

// Adds the gradient of formula.root to formula.graph, then emits.
GlslFormula emitFormulaGlsl(Formula& formula);

// The contour block (shading.contours): `#define RT_CONTOURS` and
//   vec4 zs_contour(vec3 p)   // xyz = gradient of g, w = g; w is NaN where either is undefined
// for a function g of x, y, z. Joined to the formula block; g may not have parameters
// (returns "" if it has: the scene refuses such a function).
std::string emitContourGlsl(Formula& function);

// How one surface of several is lit (its front and back material, ambient already times
// the scene's ambient light: (ambient, diffuse, specular, shininess)).
struct SurfaceLook {
  std::array<double, 3> frontColor{}, backColor{};
  std::array<double, 4> frontPhong{}, backPhong{};
};

// The curves where two surfaces meet, highlighted (highlights.intersection).
struct IntersectionLook {
  bool enabled = true;
  double tolerance = 0.02;
  std::array<double, 3> color{};
};

// The surfaces block, for a scene of several surfaces traced as the product of their
// functions (scene_io.hpp, parseSceneFormula): `#define RT_SURFACES n` and
//   vec4 zs_surfaceAt(vec3 p, out int surface, out float other)
// which returns the gradient (xyz) and value (w) of the surface p lies on (the one nearest
// to first order, |F| / |grad F|), its index, and the same distance to the nearest other
// one; the materials of surfaces 1.. (surface 0 takes the frame's) as zs_surfaceFront* /
// zs_surfaceBack* constants, and, when the highlight is on, RT_INTERSECTION with its
// tolerance and color. `roots` are the surfaces' functions, nodes of g (which must be the
// graph of the formula block, so parameters share zs_params); `looks` has one entry per root.
std::string emitSurfacesGlsl(Graph& g, const std::vector<NodeId>& roots,
                             const std::vector<SurfaceLook>& looks,
                             const IntersectionLook& intersection);

}  // namespace zs
