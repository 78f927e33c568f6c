#pragma once
// SURFER's lights and materials onto zeroset's and back. SURFER has up to 8 point lights
// that sit in camera space (they turn with the camera) and Phong materials with ambient,
// diffuse and specular weights per side; the mapping and what it cannot keep are listed in
// docs/jsurf.md. `notes` collects one line per thing shown differently.
#include <string>
#include <vector>

#include "jsurf/surfer_frame.hpp"
#include "jsurf/surfer_scene.hpp"
#include "render/settings.hpp"

namespace zs::jsurf {

// SURFER's lights stay fixed to the camera (lights.space = "camera"): `cameraToWorld` takes
// them from SURFER's camera space into the world, and `out.camera` (set first) into
// zeroset's camera coordinates, so the first picture is lit as SURFER lights it and a
// turned view as SURFER lights the turned surface.
void lightingToScene(const SurferScene& surfer, const Mat4& cameraToWorld, RenderSettings& out,
                     std::vector<std::string>& notes);

// `worldToCamera` is the inverse: zeroset's lights (in the world, or fixed to its camera)
// into SURFER's camera space;
// `radius` (the clipping sphere's) sets how far away a directional light is put.
void lightingToSurfer(const RenderSettings& render, const Mat4& worldToCamera, double radius,
                      SurferScene& out, std::vector<std::string>& notes);

}  // namespace zs::jsurf
