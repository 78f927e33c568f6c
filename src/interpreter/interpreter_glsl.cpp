#include "interpreter/interpreter_glsl.hpp"

#include "codegen/op_glsl.hpp"
#include "codegen/op_interval_glsl.hpp"
#include "interpreter/gpu_tape.hpp"

namespace zs {
namespace {

inline constexpr std::string_view kTapePointTemplate = "tape_point.frag.glsl";
inline constexpr std::string_view kTapeAffineTemplate = "tape_affine.frag.glsl";

std::string constant(const char* name, long long value, const char* type = "int") {
  return std::string("const ") + type + " " + name + " = " + std::to_string(value) +
         (std::string(type) == "uint" ? "u" : "") + ";\n";
}

bool isLeaf(Op op) {
  return opInfo(op).arity == 0;
}

// The layout of gpu_tape.hpp as GLSL constants: one definition of each code and bit.
std::string tapeConstants() {
  std::string s;
  s += constant("ZS_TAPE_REGISTERS", kTapeRegisters);
  s += constant("ZS_TAPE_ROW", 1024);
  s += constant("ZS_TAPE_UNDEFINED_BIT", kTapeUndefinedBit, "uint");
  s += constant("ZS_TAPE_DERIVATIVE_BIT", kTapeDerivativeBit, "uint");
  const std::pair<const char*, TapeCode> codes[] = {
      {"ZS_TAPE_COORDINATE", TapeCode::Coordinate},
      {"ZS_TAPE_CONSTANT", TapeCode::Constant},
      {"ZS_TAPE_PARAM", TapeCode::Param},
      {"ZS_TAPE_DIRECTION", TapeCode::Direction},
      {"ZS_TAPE_SCALE", TapeCode::Scale},
      {"ZS_TAPE_SCALE_DIRECTION", TapeCode::ScaleDirection},
      {"ZS_TAPE_MULK", TapeCode::MulK},
      {"ZS_TAPE_SINCOS", TapeCode::SinCos},
      {"ZS_TAPE_SETTLE", TapeCode::Settle}};
  for (const auto& [name, code] : codes) s += constant(name, static_cast<int>(code));
  return s;
}

// A GLSL function `header` that switches over the opcode table: one `case` per opcode that
// `rhs` spells (it returns "" for the ones the dispatch leaves out), then `fallback`.
template <class Rhs>
std::string opSwitch(const std::string& header, const char* fallback, Rhs rhs) {
  std::string s = header + "  switch (code) {\n";
  for (int i = 0; i < kOpCount; ++i) {
    const std::string r = rhs(static_cast<Op>(i));
    if (r.empty()) continue;
    s += "    case " + std::to_string(i) + ": return " + r + ";  // " +
         std::string(kOpTable[i].enumName) + "\n";
  }
  return s + "  }\n  return " + fallback + ";\n}\n";
}

// zs_tapeOp: every opcode's point statement, spelled as the formula block spells it.
std::string pointDispatch(bool polynomialOnly) {
  return opSwitch(
      "// One operation at a point; flag: set where it is undefined (the formula block's zs_u).\n"
      "float zs_tapeOp(int code, vec3 p, float a, float b, uint w, inout bool flag) {\n",
      "0.0", [&](Op op) -> std::string {
        if ((polynomialOnly && !isPolynomialOp(op)) || opInfo(op).kind == OpKind::Internal)
          return {};  // internal operations never reach a tape (gpu_tape.cpp)
        switch (op) {
          case Op::Const:
            return "uintBitsToFloat(w)";
          case Op::VarX:
            return "p.x";
          case Op::VarY:
            return "p.y";
          case Op::VarZ:
            return "p.z";
          case Op::Param:
            return "zs_params[int(w) & " + std::to_string(kTapeMaxParams - 1) + "]";
          case Op::PowI:
            return "zs_tapePowi(a, int(w), flag)";
          default:
            return glslOpExpression(op, "a", "b", "flag");
        }
      });
}

// zs_tapeAffineRule: every non-leaf opcode's affine rule, as the interval block writes it.
std::string affineDispatch(bool polynomialOnly) {
  return opSwitch(
      "// One operation's affine rule (the generated interval block's zsa_* call); k: PowI's "
      "exponent.\n"
      "vec4 zs_tapeAffineRule(int code, vec4 a, vec4 b, int k, inout bool flag) {\n",
      "zsa_whole()", [&](Op op) -> std::string {
        if (isLeaf(op) || (polynomialOnly && !isPolynomialOp(op)) ||
            opInfo(op).kind == OpKind::Internal)
          return {};
        // The exponent is data here: both of the emitter's choices, chosen at run time.
        if (op == Op::PowI)
          return "k == 2 ? " + glslAffineOpExpression(op, "a", "", 2, "flag") + " : zsa_powi(a, k)";
        return glslAffineOpExpression(op, "a", opInfo(op).arity == 2 ? "b" : "", 0, "flag");
      });
}

// base^k with the formula block's association (codegen/body_writer.cpp): the squares
// s(i) = base^(2^i), then s(h-1) * s(h-1) times the squares of the lower set bits, and 1
// divided by that for k < 0.
const char* kPowi = R"(float zs_tapePowi(float base, int k, inout bool flag) {
  if (k == 0) return 1.0;
  int m = abs(k), h = 0;
  while ((m >> (h + 1)) != 0) ++h;
  float r = base;
  if (h > 0) {
    float top = base;
    for (int j = 1; j < h; ++j) top = top * top;
    r = top * top;
    float square = base;
    for (int i = 0; i < h; ++i) {
      if (((m >> i) & 1) != 0) r = r * square;
      square = square * square;
    }
  }
  return k > 0 ? r : zs_div(1.0, r, flag);
}
)";

}  // namespace

std::string interpreterFragmentShader(bool sampling, bool polynomialOnly, ShaderDialect dialect) {
  GlslFormula formula;
  formula.paramCount = kTapeMaxParams;
  formula.source =
      "// zeroset tape interpreter block (src/interpreter): any formula, from its tape.\n";
  formula.source += "uniform float zs_params[" + std::to_string(kTapeMaxParams) + "];\n";
  formula.source += tapeConstants() + kPowi + pointDispatch(polynomialOnly);
  if (!polynomialOnly) formula.source += "#define ZS_TAPE_EVERY_OPERATION\n";
  formula.source += shaderTemplate(kTapePointTemplate);
  if (sampling) return assembleFragmentShader(formula, {}, dialect);
  IntervalGlsl interval{affineDispatch(polynomialOnly) +
                        std::string(shaderTemplate(kTapeAffineTemplate))};
  return assembleFragmentShader(formula, interval, {}, dialect);
}

}  // namespace zs
