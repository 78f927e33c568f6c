#include "expr/opcode.hpp"

namespace zs {

std::optional<Op> functionByName(std::string_view name) {
  for (int i = 0; i < kOpCount; ++i) {
    if (kOpTable[i].kind == OpKind::Call && kOpTable[i].spelling == name) return Op(i);
  }
  if (name == "ln") return Op::Log;
  return std::nullopt;
}

}  // namespace zs
