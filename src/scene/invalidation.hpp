#pragma once
// What an edit of a scene invalidates, stated once: every key of the .surf schema
// (schema.cpp) carries its flags, and invalidation() compares two scenes key by key. The
// session (src/session) rebuilds exactly what this says, and so does every front end through
// it; `zeroset render --animate` asks the same of each frame.
//
// Nothing set: only the frame's uniforms change (the camera, a color, epsilon), a redraw.
// Variant: the program variant, the #defines put before the same shader text (lights,
// supersampling, reflection: render/program_variant.hpp); the tracer compiles it when it
// draws, no CPU stage runs. Shader: the generated shader text (pipeline::prepareShader).
// Geometry: the octree and the box hierarchy (pipeline::prepareGeometry).
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace zs {

using Invalidation = unsigned;

namespace invalidates {
inline constexpr Invalidation Frame = 0;
inline constexpr Invalidation Variant = 1u << 0;
inline constexpr Invalidation Shader = 1u << 1;
inline constexpr Invalidation Geometry = 1u << 2;
// What a key invalidates only in some scenes; invalidation() resolves these to Shader.
// Several surfaces: each surface's materials, the ambient light and the intersection
// highlight are constants of the surfaces block of the shader.
inline constexpr Invalidation ShaderIfSeveralSurfaces = 1u << 3;
// highlights.singular on: the marked points are constants of the shader, found in the
// domain with the parameters' values.
inline constexpr Invalidation ShaderIfMarked = 1u << 4;
// A new formula (or level): everything the CPU makes.
inline constexpr Invalidation Surface = Shader | Geometry;
}  // namespace invalidates

// What going from `before` to `after` invalidates (Variant, Shader and Geometry only: the
// conditional flags resolved against either scene). The formula, the level and the
// [[surface]] list invalidate the surface; a parameter its geometry (and its shader where
// points are marked); the lights and clip planes their variant. With `formulaParams` given
// (the names the prepared surface's formula uses), parameters it does not use change nothing.
Invalidation invalidation(const Scene& before, const Scene& after,
                          const std::vector<std::string>* formulaParams = nullptr);

}  // namespace zs
