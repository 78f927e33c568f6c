#pragma once
// The tiles of a picture that the interval method's beam pass (raytrace_beam.frag.glsl)
// found clear: it writes one (start, segment) texel per tile of tile x tile pixels, and
// start = FLT_MAX says that no ray of the tile has a root in the box where hits can lie.
// Tile skipping (render/ray_tracer.cpp) marks those tiles off in the stencil buffer so that
// the main pass never starts their fragments: on llvmpipe a fragment whose walk is empty
// still runs every loop body once (each group of pixels runs a loop at least once), but one
// that fails the stencil test before its shader costs nothing (docs/renderer.md).
#include <span>
#include <vector>

namespace zs {

// True where a beam texel's start says that the tile's rays hit nothing.
bool beamTileIsClear(float start);

// The clear tiles of a picture of width x height pixels, merged into horizontal runs: two
// triangles per run as clip-space (x, y) pairs, 12 floats a run. `beam` holds tilesX x
// tilesY texels of (start, segment), bottom row first (as glReadPixels returns them); a
// size that does not match gives no runs (then every tile is shaded: nothing is lost).
std::vector<float> clearTileRuns(std::span<const float> beam, int tilesX, int tilesY, int tile,
                                 int width, int height);

}  // namespace zs
