#pragma once
// The single table of operations. Every stage (printer, derivative, point and interval
// evaluators, GLSL emitter) switches over Op; -Werror=switch catches a forgotten case.
#include <cstdint>
#include <optional>
#include <string_view>

namespace zs {

// X(Enum, spelling, arity, kind, glsl)
//   spelling: how the parser and printer write it (function name, operator symbol)
//   kind:     Leaf, Prefix (unary minus), Infix (binary operator), Call (function syntax),
//             Internal (built by zeroset, never parsed; printed with call syntax)
//   glsl:     the GLSL spelling the code generator starts from ("" = emitted specially)
#define ZS_OPCODES(X)                                                                     \
  X(Const, "", 0, Leaf, "")                                                               \
  X(VarX, "x", 0, Leaf, "")                                                               \
  X(VarY, "y", 0, Leaf, "")                                                               \
  X(VarZ, "z", 0, Leaf, "")                                                               \
  X(Param, "", 0, Leaf, "")                                                               \
  X(Neg, "-", 1, Prefix, "-")                                                             \
  X(Add, "+", 2, Infix, "+")                                                              \
  X(Sub, "-", 2, Infix, "-")                                                              \
  X(Mul, "*", 2, Infix, "*")                                                              \
  X(Div, "/", 2, Infix, "/")                                                              \
  X(PowI, "^", 1, Infix, "") /* exponent: Node::ival */                                   \
  X(Pow, "pow", 2, Call, "pow")                                                           \
  X(Sin, "sin", 1, Call, "sin")                                                           \
  X(Cos, "cos", 1, Call, "cos")                                                           \
  X(Tan, "tan", 1, Call, "tan")                                                           \
  X(Asin, "asin", 1, Call, "asin")                                                        \
  X(Acos, "acos", 1, Call, "acos")                                                        \
  X(Atan, "atan", 1, Call, "atan")                                                        \
  X(Atan2, "atan2", 2, Call, "atan")                                                      \
  X(Sinh, "sinh", 1, Call, "sinh")                                                        \
  X(Cosh, "cosh", 1, Call, "cosh")                                                        \
  X(Tanh, "tanh", 1, Call, "tanh")                                                        \
  X(Exp, "exp", 1, Call, "exp")                                                           \
  X(Log, "log", 1, Call, "log")                                                           \
  X(Sqrt, "sqrt", 1, Call, "sqrt")                                                        \
  X(Cbrt, "cbrt", 1, Call, "")                                                            \
  X(Abs, "abs", 1, Call, "abs")                                                           \
  X(Sign, "sign", 1, Call, "sign")                                                        \
  X(Floor, "floor", 1, Call, "floor")                                                     \
  X(Ceil, "ceil", 1, Call, "ceil")                                                        \
  X(Min, "min", 2, Call, "min")                                                           \
  X(Max, "max", 2, Call, "max")                                                           \
  /* b where a is defined, else 0: the one operation that stops undefinedness; several */ \
  /* surfaces' product takes each as "F where defined, else 1" (scene/surfaces.cpp) */    \
  X(IfDefined, "ifdefined", 2, Internal, "")

enum class OpKind : std::uint8_t { Leaf, Prefix, Infix, Call, Internal };

enum class Op : std::uint8_t {
#define ZS_ENUM(name, spelling, arity, kind, glsl) name,
  ZS_OPCODES(ZS_ENUM)
#undef ZS_ENUM
};

struct OpInfo {
  std::string_view enumName;
  std::string_view spelling;
  int arity;
  OpKind kind;
  std::string_view glsl;
};

inline constexpr OpInfo kOpTable[] = {
#define ZS_INFO(name, spelling, arity, kind, glsl) {#name, spelling, arity, OpKind::kind, glsl},
    ZS_OPCODES(ZS_INFO)
#undef ZS_INFO
};

inline constexpr int kOpCount = int(sizeof(kOpTable) / sizeof(kOpTable[0]));

constexpr const OpInfo& opInfo(Op op) {
  return kOpTable[static_cast<int>(op)];
}

// The function named `name` in the formula language (including aliases such as "ln"),
// or nothing.
std::optional<Op> functionByName(std::string_view name);

}  // namespace zs
