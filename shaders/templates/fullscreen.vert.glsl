#version 330 core
// Two triangles covering the viewport (thesis 4.4.2), generated from gl_VertexID so no
// vertex buffer is needed; an empty VAO is bound when drawing. Positions pass through
// unchanged (thesis Listing 4.1); the fragment shader derives its pixel from gl_FragCoord.
const vec2 kCorners[6] = vec2[6](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(1.0, 1.0),
                                 vec2(-1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, 1.0));

void main() {
  gl_Position = vec4(kCorners[gl_VertexID], 0.0, 1.0);
}
