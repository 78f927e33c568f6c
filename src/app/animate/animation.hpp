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
// What a frame rebuilds is what the schema says its change invalidates
// (scene/invalidation.hpp), as for every edit: a parameter that appears in F changes the
// octree (a tree built for one value may drop boxes the surface reaches at another), one F
// does not use and camera.orbit change nothing but uniforms, and so on.
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

// Whether the frames need more than new uniforms: the schema's rule (scene/invalidation.hpp)
// between the first and the last frame's scenes says Shader or Geometry.
bool rebuildsEachFrame(const Animation& anim, const Scene& base);

// The eye of `camera` turned by `degrees` about the axis through its target along its up.
Vec3 orbitEye(const Camera& camera, double degrees);

}  // namespace zs::app
