#include "codegen/emit_interval_glsl.hpp"

#include <cmath>
#include <vector>

#include "codegen/affine_lowering.hpp"
#include "codegen/body_writer.hpp"
#include "codegen/glsl_literal.hpp"
#include "codegen/op_interval_glsl.hpp"

namespace zs {
namespace {

std::string floatText(float v) {
  if (std::isinf(v)) return v > 0 ? "ZSI_INF" : "(-ZSI_INF)";
  std::string t = glslFloatLiteral(v).text;
  return !t.empty() && t[0] == '-' ? "(" + t + ")" : t;
}

// One `vec4 aN = zsa_<rule>(...);` per step of the lowered program (`vec4 sN` for settled
// forms); leaves are written inline where they are used.
struct Bodies {
  std::string f, df;              // F's statements, then those only dF/dt needs
  std::string fResult, dfResult;  // the settled forms of F and dF/dt
  // With IfDefined (body_writer.hpp says why), each step has flags of its own: where it is
  // defined nowhere on the segment (u_), where only somewhere (p_, zsi_partial's share).
  // Then F's and dF/dt's, as GLSL bool expressions.
  bool perStep = false;
  std::string fUndefined, fPartial, dfUndefined, dfPartial;
};

Bodies writeSteps(const AffineProgram& program) {
  static constexpr const char* kAxis[] = {"AX", "AY", "AZ"};
  static constexpr const char* kDirection[] = {"d.x", "d.y", "d.z"};
  const std::vector<AffineStep>& steps = program.steps;
  std::vector<std::string> names(steps.size());
  std::size_t next = 0;
  Bodies out;
  for (const AffineStep& s : steps) out.perStep = out.perStep || s.op == Op::IfDefined;
  std::vector<std::string> undefined(steps.size(), "false"), partial(steps.size(), "false");
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const AffineStep& s = steps[i];
    std::string& body = s.derivativeOnly ? out.df : out.f;
    std::string flag = s.derivativeOnly ? "zs_ug" : "zs_u";
    auto name = [&](std::int32_t v) -> const std::string& { return names[std::size_t(v)]; };
    auto declare = [&](const std::string& rhs) {
      names[i] = "a" + std::to_string(next++);
      body += "  vec4 " + names[i] + " = " + rhs + ";\n";
    };
    if (out.perStep && s.kind == AffineStep::Kind::Rule && s.op == Op::IfDefined) {
      // b where a is defined, else 0: 0 where a is defined nowhere, b where everywhere, and
      // where only somewhere b's range joined by 0 (a jump there: partial).
      const std::string ua = "(" + undefined[std::size_t(s.a)] + ")";
      const std::string pa = "(" + partial[std::size_t(s.a)] + ")";
      const std::string ub = "(" + undefined[std::size_t(s.b)] + ")";
      const std::string pb = "(" + partial[std::size_t(s.b)] + ")";
      const std::string& b = name(s.b);
      declare(ua + " ? zsa_const(0.0) : (" + pa + " ? (" + ub +
              " ? zsa_const(0.0) : " + "zsa_fromInterval(vec2(min(zsa_range(" + b +
              ").x, 0.0), max(zsa_range(" + b + ").y, 0.0)))) : " + b + ")");
      undefined[i] = "u_" + names[i];
      partial[i] = "p_" + names[i];
      body += "  bool " + undefined[i] + " = !" + ua + " && !" + pa + " && " + ub + ";\n";
      body += "  bool " + partial[i] + " = !" + ua + " && (" + pa + " || " + pb + ");\n";
      continue;
    }
    if (out.perStep) {
      // The operands' flags; a rule's own go to u_ (its flag argument) and zsi_partial.
      std::string u = undefined[std::size_t(std::max(s.a, 0))];
      std::string p = partial[std::size_t(std::max(s.a, 0))];
      if (s.b >= 0 && s.kind != AffineStep::Kind::SinCos) {
        u = glslOr(u, undefined[std::size_t(s.b)]);
        p = glslOr(p, partial[std::size_t(s.b)]);
      }
      if (s.a < 0) u = p = "false";
      if (s.kind == AffineStep::Kind::Constant && s.nan) u = "true";
      const std::size_t mine = next;  // the name the step's value gets
      if (s.kind == AffineStep::Kind::Rule) {
        flag = "u_a" + std::to_string(mine);
        body += "  bool " + flag + " = " + u + ";\n  zsi_partial = false;\n";
        u = flag;  // its partial flag follows the rule (below)
      }
      undefined[i] = u;
      partial[i] = p;
      if (s.kind == AffineStep::Kind::SinCos) {
        undefined[i + 1] = u;
        partial[i + 1] = p;
      }
    }
    switch (s.kind) {
      case AffineStep::Kind::Coordinate:
        names[i] = kAxis[s.ival];
        break;
      case AffineStep::Kind::Param:
        names[i] = "zsa_point(zs_params[" + std::to_string(s.ival) + "])";
        break;
      case AffineStep::Kind::Direction:
        names[i] = std::string("zsa_const(") + kDirection[s.ival] + ")";
        break;
      case AffineStep::Kind::Constant:
        if (s.nan) {  // a NaN constant: F is undefined wherever it is used
          names[i] = "vec4(0.0)";
          if (!out.perStep) body += "  " + flag + " = true;  // constant NaN\n";
        } else if (s.lo == s.hi) {
          names[i] = "zsa_const(" + floatText(s.lo) + ")";
        } else {
          names[i] = "zsa_fromInterval(vec2(" + floatText(s.lo) + ", " + floatText(s.hi) + "))";
        }
        break;
      case AffineStep::Kind::Rule:
        declare(glslAffineOpExpression(s.op, name(s.a), s.b < 0 ? std::string() : name(s.b), s.ival,
                                       flag));
        if (out.perStep) {  // the rule's own partiality, with its operands'
          partial[i] = "p_" + names[i];
          const std::string operands =
              glslOr(partial[std::size_t(s.a)],
                     s.b < 0 ? std::string("false") : partial[std::size_t(s.b)]);
          body += "  bool " + partial[i] + " = " + glslOr("zsi_partial", operands) + ";\n";
        }
        break;
      case AffineStep::Kind::Scale:
        declare("zsa_scale(" + name(s.a) + ", " + floatText(s.lo) + ")");
        break;
      case AffineStep::Kind::ScaleDirection:
        declare("zsa_scale(" + name(s.a) + ", " + kDirection[s.ival] + ")");
        break;
      case AffineStep::Kind::MulK:
        declare("zsa_mulk(" + name(s.a) + ", " + name(s.b) + ")");
        break;
      case AffineStep::Kind::SinCos: {
        names[i] = "a" + std::to_string(next++);
        names[i + 1] = "a" + std::to_string(next++);
        const std::string& sn = s.op == Op::Sin ? names[i] : names[i + 1];
        const std::string& cs = s.op == Op::Sin ? names[i + 1] : names[i];
        body += "  vec4 " + sn + ", " + cs + ";\n";
        body += "  zsa_sincos(" + name(s.a) + ", " + sn + ", " + cs + ");\n";
        break;
      }
      case AffineStep::Kind::Partner:
        break;  // named with its SinCos
      case AffineStep::Kind::Settle:
        names[i] = "s" + std::to_string(next++);
        body += "  vec4 " + names[i] + " = zsa_settle(" + name(s.a) + ", " +
                std::to_string(s.ival) + ".0);\n";
        break;
    }
  }
  out.fResult = names[std::size_t(program.f)];
  out.dfResult = names[std::size_t(program.df)];
  if (out.perStep) {
    out.fUndefined = undefined[std::size_t(program.f)];
    out.fPartial = partial[std::size_t(program.f)];
    out.dfUndefined = undefined[std::size_t(program.df)];
    out.dfPartial = partial[std::size_t(program.df)];
  }
  return out;
}

}  // namespace

IntervalGlsl emitIntervalGlsl(const Graph& graph, NodeId f) {
  std::string s =
      "// zeroset interval formula block (generated by src/codegen): F and dF/dt along a ray "
      "segment.\n";
  // The nodes as affine forms along the segment t = tm + h tau (vec4 (c, s, r, m),
  // affine_prelude.frag.glsl); operations without a first-order rule use their interval
  // rule (zsi_*) on the operands' ranges.
  const Bodies ray = writeSteps(lowerAffine(graph, f));
  s += "// F and dF/dt as affine forms in tau along the segment t = tm + h tau.\n";
  s += "void zs_FAffine(vec3 o, vec3 d, float tm, float h, out vec3 F, out vec2 D, out bool "
       "partial) {\n";
  s += "  bool zs_u = false;   // F is defined nowhere on the segment\n";
  s += "  bool zs_ug = false;  // dF/dt is defined nowhere on the segment\n";
  s += "  zsi_partial = false;\n";
  s += "  vec4 AX = zsa_var(o.x, d.x, tm, h), AY = zsa_var(o.y, d.y, tm, h), "
       "AZ = zsa_var(o.z, d.z, tm, h);\n";
  s += ray.f;
  if (ray.perStep) {
    s += "  zs_u = " + ray.fUndefined + ";\n  partial = " + ray.fPartial + ";\n";
    s += ray.df;
    s += "  zs_ug = " + ray.dfUndefined + ";\n";
    s += "  zsa_finish(" + ray.fResult + ", " + ray.dfResult + ", zs_u, zs_ug || " +
         glslOr(ray.fPartial, ray.dfPartial) + ", F, D);\n}\n";
    return {s};
  }
  s += "  partial = zsi_partial;\n";
  s += ray.df;
  s += "  zsa_finish(" + ray.fResult + ", " + ray.dfResult +
       ", zs_u, zs_ug || zsi_partial, F, D);\n}\n";
  return {s};
}

}  // namespace zs
