// The frame's uniform values (frame_uniforms.hpp, shared with the web page) into GL.
#include <glad/gl.h>

#include "render/frame_uniforms.hpp"
#include "render/ray_tracer.hpp"

namespace zs {
namespace {

void applyUniforms(ProgramCache& programs, unsigned program,
                   const std::vector<UniformValue>& values) {
  for (const UniformValue& u : values) {
    const int location = programs.uniform(program, u.name.c_str());
    if (location < 0) continue;  // not read by this variant: the driver removed it
    const float* v = u.values.data();
    switch (u.kind) {
      case UniformValue::Kind::Int:
        glUniform1i(location, u.integer);
        break;
      case UniformValue::Kind::Float:
        glUniform1f(location, v[0]);
        break;
      case UniformValue::Kind::Vec2:
        glUniform2f(location, v[0], v[1]);
        break;
      case UniformValue::Kind::Vec3:
        glUniform3f(location, v[0], v[1], v[2]);
        break;
      case UniformValue::Kind::Vec4:
        glUniform4f(location, v[0], v[1], v[2], v[3]);
        break;
      case UniformValue::Kind::Mat4:
        glUniformMatrix4fv(location, 1, GL_FALSE, v);
        break;
      case UniformValue::Kind::FloatArray:
        glUniform1fv(location, GLsizei(u.values.size()), v);
        break;
    }
  }
}

}  // namespace

int RayTracer::setUniforms(unsigned program, const RenderSettings& s, const Domain& clip, int width,
                           int height) {
  FrameInputs in;
  in.hierarchy = &hierarchy_;
  in.params = params_;
  in.width = width;
  in.height = height;
  if (bandRows_ > 0) {  // renderBand: `height` is the band's, the uniforms the picture's
    in.height = fullHeight_;
    in.bandTop = bandTop_;
    in.bandHeight = bandRows_;
  }
  in.proxy = proxy_;
  in.tangentRoots = tangentRoots_;
  in.curvatureRange = curvatureRange_;
  const FrameUniforms frame = frameUniforms(s, clip, in);
  applyUniforms(programs_, program, frame.values);
  return frame.vertices;
}

}  // namespace zs
