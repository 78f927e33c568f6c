// ---- tape_point.frag.glsl (interpreter stage): zs_F and zs_FGrad run from data, not
// compiled from the formula: the tape (src/interpreter/gpu_tape.hpp) holds one instruction
// per texel, its code, destination and flag bits in x, operand registers in y and z, a
// constant, parameter index or exponent in w. Follows the generated dispatch (zs_tapeOp,
// src/interpreter/interpreter_glsl.cpp), so every operation means what the formula block's
// statement for it means; the ray tracer that follows cannot tell the two apart.
#ifdef GL_ES
// WebGL2 has no buffer textures: the texels in rows of ZS_TAPE_ROW.
uniform highp usampler2D zs_tape;
uvec4 zs_tapeAt(int i) { return texelFetch(zs_tape, ivec2(i % ZS_TAPE_ROW, i / ZS_TAPE_ROW), 0); }
#else
uniform usamplerBuffer zs_tape;
uvec4 zs_tapeAt(int i) { return texelFetch(zs_tape, i); }
#endif

float zs_reg[ZS_TAPE_REGISTERS];

int zs_tapeDestination(uint x) { return int((x >> 8u) & 4095u); }
int zs_tapeRegister(uint r) { return int(r) & (ZS_TAPE_REGISTERS - 1); }

// Runs the point program [begin, end); domain errors go to u, or to ug for an instruction
// only the gradient needs.
void zs_runPoint(vec3 p, int begin, int end, inout bool u, inout bool ug) {
  for (int i = begin; i < end; ++i) {
    uvec4 c = zs_tapeAt(i);
    bool flag = (c.x & ZS_TAPE_UNDEFINED_BIT) != 0u;
    float r = zs_tapeOp(int(c.x & 255u), p, zs_reg[zs_tapeRegister(c.y)],
                        zs_reg[zs_tapeRegister(c.z)], c.w, flag);
    zs_reg[zs_tapeDestination(c.x)] = r;
    if ((c.x & ZS_TAPE_DERIVATIVE_BIT) != 0u) ug = ug || flag;
    else u = u || flag;
  }
}

float zs_F(vec3 p) {
  uvec4 programs = zs_tapeAt(0);
  bool u = false, ug = false;
  zs_runPoint(p, int(programs.x), int(programs.y), u, ug);
  return zs_finishF(zs_reg[zs_tapeRegister(zs_tapeAt(3).x)], u);
}

vec4 zs_FGrad(vec3 p) {
  uvec4 programs = zs_tapeAt(0);
  bool u = false, ug = false;
  zs_runPoint(p, int(programs.z), int(programs.w), u, ug);
  uvec4 o = zs_tapeAt(2);
  return zs_finishFGrad(vec3(zs_reg[zs_tapeRegister(o.y)], zs_reg[zs_tapeRegister(o.z)],
                             zs_reg[zs_tapeRegister(o.w)]),
                        zs_reg[zs_tapeRegister(o.x)], u, ug);
}
