#pragma once
// A picture as zeroset traced it against an independent reference in double precision, for
// the exactness tests (record_surfaces_test.cpp) and the zs_reference_compare tool. The
// reference samples f(t) = F(o + t d) and f'(t) = grad F . d in double along each pixel ray
// (32 D samples, D the degree, 8 for other formulas) and bisects the first root; where the
// render draws nearer than that, outward-rounded interval arithmetic decides whether F has
// a root within the tangent tolerance (or tracing.epsilon) of the point drawn.
#include <string>

#include "pipeline/pipeline.hpp"
#include "render/ray_tracer.hpp"
#include "scene/scene.hpp"

namespace zs::test {

struct ReferenceCounts {
  int hits = 0;         // pixels where the reference hits, of those not left out
  int ghost = 0;        // drawn nearer than the first root, with no root within the tolerance
  int missed = 0;       // nothing drawn, or something deeper, where the reference hits
  int leftOut = 0;      // the reference's answer changes within half a pixel: either is right
  std::string details;  // one line per ghost or missed pixel
};

// `frame` is `surface` traced at size x size with `scene`'s camera and domain.
ReferenceCounts compareWithReference(const Scene& scene, const PreparedSurface& surface,
                                     const Frame& frame, int size);

// SURFER's framing of a scene whose domain is a ball: the box of the same half-width, which
// keeps the far parts of the surface in the picture.
Domain boxOfBall(const Domain& ball);

}  // namespace zs::test
