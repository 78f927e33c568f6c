#include "interpreter/gpu_tape.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_set>

#include "codegen/affine_lowering.hpp"

namespace zs {
namespace {

std::uint32_t bitsOf(float v) {
  std::uint32_t u;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

std::uint32_t code(Op op) {
  return static_cast<std::uint32_t>(op);
}
std::uint32_t code(TapeCode c) {
  return static_cast<std::uint32_t>(c);
}

// One instruction before registers are assigned: the values it defines and reads.
struct Pending {
  std::uint32_t x = 0;               // code and flag bits
  std::int32_t def = -1, def2 = -1;  // def2: SinCos's second result
  std::int32_t useA = -1, useB = -1;
  std::uint32_t z = 0, w = 0;  // words that are not registers (when useB < 0 for z)
  bool zIsDef2 = false;        // SinCos: w holds the second destination
};

// Linear-scan assignment: a value's register is free again after the instruction that reads
// it last; outputs stay live to the end. Returns the registers of `outputs`, or empty when more
// than kTapeRegisters values are live at once.
class Program {
 public:
  void add(const Pending& p) { code_.push_back(p); }

  // Appends the instructions as texels; `registersUsed` is the most live at once.
  bool emit(std::size_t valueCount, const std::vector<std::int32_t>& outputs,
            std::vector<std::uint32_t>& texels, std::vector<std::uint32_t>& outputRegisters,
            int& registersUsed) {
    std::vector<std::size_t> lastUse(valueCount, 0);
    std::vector<bool> used(valueCount, false);
    for (std::size_t i = 0; i < code_.size(); ++i) {
      for (std::int32_t v : {code_[i].useA, code_[i].useB}) {
        if (v >= 0) lastUse[std::size_t(v)] = i, used[std::size_t(v)] = true;
      }
    }
    for (std::int32_t v : outputs)
      lastUse[std::size_t(v)] = code_.size(), used[std::size_t(v)] = true;
    std::vector<std::int32_t> reg(valueCount, -1);
    std::vector<std::uint32_t> freeList;
    int next = 0;
    auto allocate = [&](std::int32_t v) -> bool {
      if (!freeList.empty()) {
        reg[std::size_t(v)] = std::int32_t(freeList.back());
        freeList.pop_back();
        return true;
      }
      if (next >= kTapeRegisters) return false;
      reg[std::size_t(v)] = next++;
      return true;
    };
    for (std::size_t i = 0; i < code_.size(); ++i) {
      const Pending& p = code_[i];
      const std::uint32_t a = p.useA >= 0 ? std::uint32_t(reg[std::size_t(p.useA)]) : 0;
      const std::uint32_t b = p.useB >= 0 ? std::uint32_t(reg[std::size_t(p.useB)]) : p.z;
      // Operands read last here free their registers before the results take one: the
      // interpreter reads both operands before it writes.
      for (std::int32_t v : {p.useA, p.useB}) {  // x * x reads one value twice: freed once
        if (v >= 0 && lastUse[std::size_t(v)] == i && reg[std::size_t(v)] >= 0) {
          freeList.push_back(std::uint32_t(reg[std::size_t(v)]));
          reg[std::size_t(v)] = -1;
        }
      }
      if (!allocate(p.def)) return false;
      if (p.def2 >= 0 && !allocate(p.def2)) return false;
      std::uint32_t w = p.zIsDef2 ? std::uint32_t(reg[std::size_t(p.def2)]) : p.w;
      texels.insert(texels.end(), {p.x | (std::uint32_t(reg[std::size_t(p.def)]) << 8), a, b, w});
      // A result nobody reads is free at once.
      for (std::int32_t v : {p.def, p.def2}) {
        if (v >= 0 && !used[std::size_t(v)]) {
          freeList.push_back(std::uint32_t(reg[std::size_t(v)]));
          reg[std::size_t(v)] = -1;
        }
      }
    }
    outputRegisters.clear();
    for (std::int32_t v : outputs) outputRegisters.push_back(std::uint32_t(reg[std::size_t(v)]));
    registersUsed = std::max(registersUsed, next);
    return true;
  }

 private:
  std::vector<Pending> code_;
};

// F (and with `withGradient` its gradient) at a point: the reachable nodes in topological
// order, values numbered by node id.
bool emitPointProgram(const Graph& g, const std::vector<NodeId>& roots, NodeId f,
                      std::vector<std::uint32_t>& texels, std::vector<std::uint32_t>& outs,
                      int& registers) {
  const std::vector<NodeId> nodes = reachable(g, roots);
  std::unordered_set<NodeId> inF;
  for (NodeId id : reachable(g, {f})) inF.insert(id);
  Program program;
  std::vector<bool> emitted(g.size(), false);
  auto add = [&](NodeId id) {
    const Node& n = g[id];
    Pending p;
    p.def = id;
    p.x = code(n.op);
    if (!inF.count(id)) p.x |= kTapeDerivativeBit;
    switch (n.op) {
      case Op::Const:
        if (n.value != n.value)
          p.x |= kTapeUndefinedBit;
        else
          p.w = bitsOf(static_cast<float>(n.value));
        break;
      case Op::Param:
      case Op::PowI:
        p.w = static_cast<std::uint32_t>(n.ival);
        break;
      default:
        break;
    }
    if (opInfo(n.op).arity > 0) p.useA = n.a;
    if (n.b != kNoNode) p.useB = n.b;
    program.add(p);
    emitted[std::size_t(id)] = true;
  };
  // Leaves are loaded right before their first reader, not where their ids put them (a
  // constant the gradient needs would otherwise hold a register through all of F).
  auto leaf = [&](NodeId id) { return opInfo(g[id].op).arity == 0; };
  for (NodeId id : nodes) {
    if (leaf(id)) continue;
    for (NodeId k : {g[id].a, g[id].b}) {
      if (k != kNoNode && leaf(k) && !emitted[std::size_t(k)]) add(k);
    }
    add(id);
  }
  for (NodeId id : roots) {
    if (!emitted[std::size_t(id)]) add(id);
  }
  std::vector<std::int32_t> outputs(roots.begin(), roots.end());
  return program.emit(g.size(), outputs, texels, outs, registers);
}

// The affine program, step for step; a Partner is SinCos's second result.
bool emitAffineProgram(const AffineProgram& ap, std::vector<std::uint32_t>& texels,
                       std::uint32_t& splitTexel, std::vector<std::uint32_t>& outs,
                       int& registers) {
  Program program;
  const std::size_t base = texels.size() / 4;
  std::size_t count = 0;
  splitTexel = 0;
  for (std::size_t i = 0; i < ap.steps.size(); ++i) {
    if (std::int32_t(i) == ap.fEnd) splitTexel = std::uint32_t(base + count);
    const AffineStep& s = ap.steps[i];
    if (s.kind == AffineStep::Kind::Partner) continue;
    Pending p;
    p.def = std::int32_t(i);
    if (s.derivativeOnly) p.x |= kTapeDerivativeBit;
    switch (s.kind) {
      case AffineStep::Kind::Coordinate:
        p.x |= code(TapeCode::Coordinate);
        p.w = std::uint32_t(s.ival);
        break;
      case AffineStep::Kind::Direction:
        p.x |= code(TapeCode::Direction);
        p.w = std::uint32_t(s.ival);
        break;
      case AffineStep::Kind::Param:
        p.x |= code(TapeCode::Param);
        p.w = std::uint32_t(s.ival);
        break;
      case AffineStep::Kind::Constant:
        p.x |= code(TapeCode::Constant);
        if (s.nan) p.x |= kTapeUndefinedBit;
        p.z = bitsOf(s.hi);
        p.w = bitsOf(s.lo);
        break;
      case AffineStep::Kind::Rule:
        p.x |= code(s.op);
        p.useA = s.a;
        p.useB = s.b;
        p.w = std::uint32_t(s.ival);
        break;
      case AffineStep::Kind::Scale:
        p.x |= code(TapeCode::Scale);
        p.useA = s.a;
        p.w = bitsOf(s.lo);
        break;
      case AffineStep::Kind::ScaleDirection:
        p.x |= code(TapeCode::ScaleDirection);
        p.useA = s.a;
        p.w = std::uint32_t(s.ival);
        break;
      case AffineStep::Kind::MulK:
        p.x |= code(TapeCode::MulK);
        p.useA = s.a;
        p.useB = s.b;
        break;
      case AffineStep::Kind::SinCos:
        // Registers: the destination holds sin, the second (w) cos, whichever came first.
        p.x |= code(TapeCode::SinCos);
        p.useA = s.a;
        p.def = s.op == Op::Sin ? std::int32_t(i) : std::int32_t(i + 1);
        p.def2 = s.op == Op::Sin ? std::int32_t(i + 1) : std::int32_t(i);
        p.zIsDef2 = true;
        break;
      case AffineStep::Kind::Settle:
        p.x |= code(TapeCode::Settle);
        p.useA = s.a;
        p.w = std::uint32_t(s.ival);
        break;
      case AffineStep::Kind::Partner:
        break;
    }
    program.add(p);
    ++count;
  }
  if (splitTexel == 0) splitTexel = std::uint32_t(base + count);
  return program.emit(ap.steps.size(), {ap.f, ap.df}, texels, outs, registers);
}

}  // namespace

bool isPolynomialOp(Op op) {
  switch (op) {
    case Op::Const:
    case Op::VarX:
    case Op::VarY:
    case Op::VarZ:
    case Op::Param:
    case Op::Neg:
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::PowI:
      return true;
    default:
      return false;
  }
}

std::variant<GpuTape, std::string> encodeGpuTape(const Graph& g, NodeId f,
                                                 const std::array<NodeId, 3>& grad) {
  if (g.params().size() > std::size_t(kTapeMaxParams))
    return "the tape interpreter takes at most " + std::to_string(kTapeMaxParams) + " parameters";
  GpuTape tape;
  std::vector<std::uint32_t>& t = tape.texels;
  t.assign(kTapeHeaderTexels * 4, 0);
  auto here = [&] { return std::uint32_t(t.size() / 4); };
  const char* tooMany = "more values are live at once than the tape interpreter has registers";

  std::vector<std::uint32_t> fOut, gradOut, affineOut;
  for (NodeId id : reachable(g, {f, grad[0], grad[1], grad[2]})) {
    if (opInfo(g[id].op).kind == OpKind::Internal)
      return "the tape interpreter runs the formula language's operations only";
    tape.polynomialOnly = tape.polynomialOnly && isPolynomialOp(g[id].op);
  }
  const std::uint32_t fBegin = here();
  if (!emitPointProgram(g, {f}, f, t, fOut, tape.pointRegisters)) return tooMany;
  const std::uint32_t gradBegin = here();
  if (!emitPointProgram(g, {f, grad[0], grad[1], grad[2]}, f, t, gradOut, tape.pointRegisters))
    return tooMany;
  const std::uint32_t affineBegin = here();
  std::uint32_t split = 0;
  if (!emitAffineProgram(lowerAffine(g, f), t, split, affineOut, tape.affineRegisters))
    return tooMany;
  const std::uint32_t end = here();
  if (tape.instructions() > kTapeMaxInstructions)
    return "the formula has more than " + std::to_string(kTapeMaxInstructions) +
           " operations, more than the tape interpreter runs";
  const std::uint32_t header[kTapeHeaderTexels * 4] = {
      fBegin,      gradBegin,    gradBegin,    affineBegin,
      affineBegin, split,        end,          0,
      gradOut[0],  gradOut[1],   gradOut[2],   gradOut[3],
      fOut[0],     affineOut[0], affineOut[1], std::uint32_t(g.params().size())};
  std::copy(std::begin(header), std::end(header), t.begin());
  return tape;
}

}  // namespace zs
