#pragma once
// The tape interpreter's shaders: one fragment shader per tracing method that draws any
// formula from its tape (gpu_tape.hpp) instead of from code generated for it, compiled once.
// Its formula block defines zs_F and zs_FGrad (shaders/templates/tape_point.frag.glsl) and,
// for the interval method, zs_FAffine (tape_affine.frag.glsl) over a dispatch generated here
// from the opcode table with the code generator's own spelling of every operation
// (codegen/op_glsl.hpp, op_interval_glsl.hpp); the ray tracers around them are the usual
// templates. No curvature colorings (no second derivatives) and no singular-point markers:
// the formula's own shader draws those.
#include <string>

#include "codegen/shader_assembly.hpp"

namespace zs {

// The interpreter's fragment shader: the interval march for the exact methods (Bernstein and
// interval: the first picture of a polynomial is exact either way), the thesis' sampling
// march for `sampling`. `polynomialOnly` leaves out every operation but those of polynomials
// (isPolynomialOp): a software rasterizer such as llvmpipe runs every branch of the
// dispatch for every instruction, so a dispatch with fewer operations runs a polynomial's
// tape several times faster; GpuTape::polynomialOnly says which of the two a tape needs.
std::string interpreterFragmentShader(bool sampling, bool polynomialOnly,
                                      ShaderDialect dialect = ShaderDialect::Gl330);

}  // namespace zs
