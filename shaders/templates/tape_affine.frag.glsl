// ---- tape_affine.frag.glsl (interpreter stage): the interval method's zs_FAffine run from
// the tape's affine program (codegen/affine_lowering.hpp, encoded by
// src/interpreter/gpu_tape.hpp): the same steps as the generated interval block, in the same
// order, with the same rules. Follows the affine prelude and the generated dispatch
// (zs_tapeAffineRule) and reads the tape through zs_tapeAt (tape_point.frag.glsl).
vec4 zs_affine[ZS_TAPE_REGISTERS];

void zs_FAffine(vec3 o, vec3 d, float tm, float h, out vec3 F, out vec2 D, out bool partial) {
  bool zs_u = false;   // F is defined nowhere on the segment
  bool zs_ug = false;  // dF/dt is defined nowhere on the segment
  zsi_partial = false;
  partial = false;
  uvec4 program = zs_tapeAt(1);  // begin, where dF/dt's own steps begin, end
  int split = int(program.y), end = int(program.z);
  for (int i = int(program.x); i < end; ++i) {
    if (i == split) partial = zsi_partial;
    uvec4 c = zs_tapeAt(i);
    int code = int(c.x & 255u);
    bool flag = (c.x & ZS_TAPE_UNDEFINED_BIT) != 0u;
    vec4 a = zs_affine[zs_tapeRegister(c.y)], b = zs_affine[zs_tapeRegister(c.z)];
    int k = int(c.w);
    vec4 r;
    if (code < ZS_TAPE_COORDINATE) {
      r = zs_tapeAffineRule(code, a, b, k, flag);
    } else if (code == ZS_TAPE_COORDINATE) {
      r = zsa_var(o[k], d[k], tm, h);
    } else if (code == ZS_TAPE_CONSTANT) {
      float lo = uintBitsToFloat(c.w), hi = uintBitsToFloat(c.z);
      r = flag ? vec4(0.0) : lo == hi ? zsa_const(lo) : zsa_fromInterval(vec2(lo, hi));
    } else if (code == ZS_TAPE_PARAM) {
      r = zsa_point(zs_params[k]);
    } else if (code == ZS_TAPE_DIRECTION) {
      r = zsa_const(d[k]);
    } else if (code == ZS_TAPE_SCALE) {
      r = zsa_scale(a, uintBitsToFloat(c.w));
    } else if (code == ZS_TAPE_SCALE_DIRECTION) {
      r = zsa_scale(a, d[k]);
    } else if (code == ZS_TAPE_MULK) {
      r = zsa_mulk(a, b);
#ifdef ZS_TAPE_EVERY_OPERATION
    } else if (code == ZS_TAPE_SINCOS) {
      vec4 cosine;
      zsa_sincos(a, r, cosine);
      zs_affine[k] = cosine;
#endif
    } else {  // ZS_TAPE_SETTLE
      r = zsa_settle(a, float(k));
    }
    zs_affine[zs_tapeDestination(c.x)] = r;
    if ((c.x & ZS_TAPE_DERIVATIVE_BIT) != 0u) zs_ug = zs_ug || flag;
    else zs_u = zs_u || flag;
  }
  if (split == end) partial = zsi_partial;
  uvec4 outputs = zs_tapeAt(3);
  zsa_finish(zs_affine[zs_tapeRegister(outputs.y)], zs_affine[zs_tapeRegister(outputs.z)], zs_u,
             zs_ug || zsi_partial, F, D);
}
