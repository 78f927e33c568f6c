#pragma once
// The formula as data for the GPU: takes the expression graph with F and its gradient, puts
// out the texels the tape interpreter shader runs (interpreter_glsl.hpp), so a new formula
// draws through a program compiled once instead of waiting for its own shader's JIT.
//
// Three straight-line programs share one texel array (one uvec4 per texel):
//   - F at a point and F with its gradient at a point (the nodes in topological order, as
//     the formula block's zs_F and zs_FGrad compute them, codegen/emit_glsl.hpp);
//   - F and dF/dt as affine forms along a ray segment: the interval method's lowered program
//     (codegen/affine_lowering.hpp), step for step.
// Values live in registers, reused once their last reader has run, so a formula fits when at
// most kTapeRegisters of its values are live at once. docs/interpreter.md has the layout.
#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "expr/graph.hpp"

namespace zs {

inline constexpr int kTapeRegisters = 128;  // per register file (a power of two)
inline constexpr int kTapeMaxParams = 32;   // the interpreter's zs_params[] length
inline constexpr int kTapeMaxInstructions = 4000;
// Texel codes beyond the opcode table (its values are the codes of the operations
// themselves): the affine program's leaves and its rules that are not one opcode's.
enum class TapeCode : std::uint8_t {
  Coordinate = 64,
  Constant,
  Param,
  Direction,
  Scale,
  ScaleDirection,
  MulK,
  SinCos,
  Settle,
};
// Bits of a texel's x beside the code (bits 0-7) and destination register (bits 8-19).
inline constexpr std::uint32_t kTapeUndefinedBit = 1u << 30;   // a NaN constant
inline constexpr std::uint32_t kTapeDerivativeBit = 1u << 31;  // flags go to the derivative's

// The header texels: 0 = the point F program (begin, end) and the point F-and-gradient
// program (begin, end); 1 = the affine program (begin, where dF/dt's own steps begin, end);
// 2 = registers of F, dF/dx, dF/dy, dF/dz after the gradient program; 3 = the register of F
// after the F program, of F and dF/dt after the affine program, the parameter count.
inline constexpr int kTapeHeaderTexels = 4;

// The operations of polynomials: constants, x, y, z, parameters, -, +, *, integer powers.
bool isPolynomialOp(Op op);

struct GpuTape {
  std::vector<std::uint32_t> texels;  // 4 words per texel
  bool polynomialOnly = true;         // every operation isPolynomialOp (interpreter_glsl.hpp)
  int pointRegisters = 0, affineRegisters = 0;  // the most live at once
  int instructions() const { return int(texels.size() / 4) - kTapeHeaderTexels; }
};

// The tape of F (a node of g) with its gradient `grad` (gradient(g, f)), or why the
// interpreter cannot run it (too many live values, instructions or parameters).
std::variant<GpuTape, std::string> encodeGpuTape(const Graph& g, NodeId f,
                                                 const std::array<NodeId, 3>& grad);

}  // namespace zs
