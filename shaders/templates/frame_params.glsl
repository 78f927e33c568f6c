// ---- frame_params.glsl (render stage): the parameters of one frame as the fragment shader
// reads them. They are uniforms of the program, rtName for member `name` (generated from
// this block; render/ray_tracer_uniforms.cpp sets them), copied into this block of flat
// varyings by the vertex stage, and the fragment shader reads only the block: llvmpipe
// reads a uniform in a fragment shader with
// an 8-lane gather and a bounds check per lane (about 20 instructions) at every use, in
// every pass of every loop, while a flat input is interpolated once per group of pixels.
// That is a large part of a frame (docs/renderer.md). shader_assembly.cpp puts this
// file into both stages, with RT_FRAME_STORAGE defined as `out` and as `in`; bools travel
// as ints (GLSL has no bool varyings), so their uniforms are ints too. One member per line.
// On GPU drivers and WebGL2 the fragment stage reads the uniforms itself into a struct of
// these members instead (RT_FRAME_UNIFORMS; render/program_variant.hpp, FrameStorage).
RT_FRAME_STORAGE RtFrame {
  flat vec3 domainMin;  // domain box (the thesis' clipping box)
  flat vec3 domainMax;  // (the bounding box of the ball for a sphere domain)
  flat vec4 ball;  // a sphere domain's (center, radius); radius 0 when the domain is the box
  flat vec3 rootMin;  // box of the octree's leaves (hierarchy root)
  flat vec3 rootMax;
  flat float pad;  // widens the root box by the float slack of the hierarchy
  flat vec2 resolution;  // full image size in pixels (tiles only restrict the scissor)
  flat vec2 pixelOrigin;  // where the target's pixel (0, 0) lies in the full image, counted bottom-up like gl_FragCoord: (0, 0) but for a band of a taller picture (render/ray_tracer.hpp renderBand)
  flat vec3 eye;
  flat vec3 forward;
  flat vec3 right;
  flat vec3 up;
  flat float planeHalf;  // tan(fov_y/2), or height/2 when orthographic
  flat int ortho;  // bools travel as ints (0 or 1)
  flat int maxBisections;
  flat float epsilon;
  flat float tangentTolerance;  // 1e-5 of the domain diagonal (docs/renderer.md)
  flat vec3 frontColor;  // the lights are shader constants (raytrace_shading.frag.glsl)
  flat vec3 backColor;
  flat vec4 frontPhong;  // (ambient * lights.ambient, diffuse, specular, shininess)
  flat vec4 backPhong;
  flat float curvatureRange;  // curvature colorings: the value at the ends of the color map
  flat int silhouetteOn;
  flat int borderOn;
  flat float silhouetteThreshold;
  flat float borderThreshold;
  flat float primaryWeight;
  flat float opacity;
  flat vec3 silhouetteColor;
  flat vec3 borderColor;
  flat vec4 clip0;  // clip planes (unit normal, offset): the ray keeps normal . p <= offset;
  flat vec4 clip1;  // an unused plane is (0, 0, 0, 1e30)
  flat vec4 clip2;
  flat vec4 clip3;
  flat int cutOn;  // the curve where the surface meets a clip plane
  flat float cutThreshold;
  flat vec3 cutColor;
  flat float contourSpacing;  // shading.contours (raytrace_shading.frag.glsl, RT_CONTOURS)
  flat float contourWidth;
  flat vec3 contourColor;
  flat float volumeDensity;  // render.mode "volume" (raytrace_volume.frag.glsl)
  flat float volumeFalloff;
  flat float volumeRange;
  flat int volumeSteps;
  flat vec3 background;
  flat int nodeCount;  // sampling only: the hierarchy walk, leaf segments, tangent roots
  flat int firstNode;
  flat vec3 cell;  // cell size of the grid over the root box
  flat int intervals;
  flat int tangentRoots;
} rt;
