#pragma once
// `zeroset render --animate KEY=FROM:TO --frames N`: what is animated and how each frame's
// scene follows from the loaded one. Takes the --animate text and a Scene; puts out the
// scene of frame i and whether that frame needs its own octree. No GL here.
//
// KEY is params.NAME (a parameter, swept linearly from FROM to TO, both ends included),
// camera.orbit (the eye turned about the axis through camera.target along camera.up, by
// FROM to TO degrees), or any other number of the scene as --set names it
// (clip.plane.1.offset, volume.falloff, lights.source.2.intensity, domain.radius, ...),
// set through --set's checks each frame.
//
// When the octree must be rebuilt: the octree keeps the boxes where 0 may lie in F(box),
// evaluated with the parameters' values, so a parameter that appears in F changes it and
// every frame gets its own (a tree built for one value may drop boxes the surface reaches
// at another: reusing it would cut holes). A parameter F does not use, and camera.orbit,
// change no box: the octree, the box hierarchy and the shader are built once. Of the other
// keys, those of the domain, the octree and the singular-point markers rebuild every frame;
// the rest are frame parameters or program variants (clip planes, volume, lights, ...).
#include <optional>
#include <string>

#include "scene/scene.hpp"

namespace zs::app {

struct Animation {
  enum class Kind { Param, Orbit, Level, Setting };
  Kind kind = Kind::Param;
  std::string param;  // Kind::Param: the parameter's name; Kind::Setting: the key
  double from = 0, to = 1;
  int frames = 60;

  std::string key() const {
    return kind == Kind::Orbit     ? "camera.orbit"
           : kind == Kind::Level   ? "surface.level"
           : kind == Kind::Setting ? param
                                   : "params." + param;
  }
  // The animated value of frame `i` in [0, frames): from at 0, to at frames - 1.
  double valueAt(int i) const;
};

// Reads "params.NAME=FROM:TO", "surface.level=FROM:TO", "camera.orbit=FROM:TO" or
// "KEY=FROM:TO" for another key (checked against the scene by frameScene); on failure
// `error` says what is wrong and how to write it.
std::optional<Animation> parseAnimation(const std::string& text, int frames, std::string& error);

// The scene of frame `i`: `base` with the animated key set. "" on success, else the
// message (a value the scene refuses, e.g. a parameter name the formula language rejects).
std::string frameScene(const Animation& anim, const Scene& base, int i, Scene& out);

// Whether a frame needs its own octree and box hierarchy (see above): the animated
// parameter appears in `formula`, or the level moves.
bool changesOctree(const Animation& anim, const Scene& base);

// The eye of `camera` turned by `degrees` about the axis through its target along its up.
Vec3 orbitEye(const Camera& camera, double degrees);

}  // namespace zs::app
