#pragma once
// Mouse and touch motion to camera motion, for the viewer and the web page: takes the camera at the
// start of a drag and two cursor positions in window pixels (origin top-left), puts out the camera
// orbited about its target (Shoemake's arcball: the cursor lies on a virtual sphere filling the
// window, and the surface turns as if that sphere were dragged), a point (the point light) turned
// about the target the same way, or the camera moved along its line of sight by wheel steps.
// Pure math on doubles; degenerate input (zero-size window, eye on the target) is a no-op.
#include "render/settings.hpp"

namespace zs::interact {

struct DragPoints {
  double x0, y0, x1, y1;  // cursor at the press and now, window pixels
  int width, height;      // window size in the same pixels
};

// The eye (and the up vector) orbit the target opposite to the drag, so the surface appears
// to follow the cursor. Distance to the target is kept exactly.
Camera orbitCamera(const Camera& start, const DragPoints& drag);

// `point` turned about the camera's target with the drag, as if attached to the surface.
Vec3 orbitPoint(const Camera& view, const Vec3& point, const DragPoints& drag);

// A direction (a directional light's) turned with the drag the same way.
Vec3 orbitDirection(const Camera& view, const Vec3& direction, const DragPoints& drag);

// Each wheel step towards the user moves the eye 15% closer to the target (orthographic:
// shrinks the view height); the distance stays within [1e-3, 1e4].
Camera zoomCamera(const Camera& camera, double wheelSteps);

}  // namespace zs::interact
