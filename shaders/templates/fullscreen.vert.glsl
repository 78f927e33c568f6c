#version 330 core
// The geometry that starts one fragment (one ray) per pixel, chosen by rtProxy:
//  0 Two triangles covering the viewport (thesis 4.4.2, Listing 4.1), 6 vertices;
//    positions pass through unchanged.
//  1 The box where hits can lie (domain box clipped to the hierarchy's root box, widened
//    by a pixel's footprint), 36 vertices, front faces culled: each pixel whose ray meets
//    the box gets exactly one fragment; all other pixels keep the cleared background. On
//    llvmpipe every fragment runs every branch of the shader (masked SIMD), so pixels that
//    cannot hit anything are better never started.
//  2 Rectangles in clip space from the vertex buffer rtTileCorner: the tiles that tile
//    skipping marks off in the stencil buffer (render/beam_tiles.hpp).
// 0 and 1 need no vertex buffer (gl_VertexID). The fragment shader derives its pixel from
// gl_FragCoord, not from here.
// It also hands the frame's parameters to the fragment shader as flat varyings
// (frame_params.glsl, inserted after #version by shader_assembly.cpp with the uniforms and
// rtCopyFrame() it generates from that block).
uniform int rtProxy;
layout(location = 0) in vec2 rtTileCorner;  // rtProxy 2 only
uniform mat4 rtViewProj;  // world -> clip, the camera contract of docs/camera.md
uniform vec3 rtBoxMin, rtBoxMax;
const vec2 kCorners[6] = vec2[6](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(1.0, 1.0),
                                 vec2(-1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, 1.0));
// Box corner c has x = bit 0, y = bit 1, z = bit 2; triangles wind counter-clockwise seen
// from outside.
const int kBox[36] = int[36](0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                             2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5);

void main() {
  rtCopyFrame();  // the frame's uniforms into the flat block (shader_assembly.cpp)
  if (rtProxy == 0) {
    gl_Position = vec4(kCorners[gl_VertexID % 6], 0.0, 1.0);
    return;
  }
  if (rtProxy == 2) {
    gl_Position = vec4(rtTileCorner, 0.0, 1.0);
    return;
  }
  int c = kBox[gl_VertexID];
  vec3 corner = mix(rtBoxMin, rtBoxMax, vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1));
  gl_Position = rtViewProj * vec4(corner, 1.0);
}
