#include "codegen/emit_ray_polynomial.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "codegen/body_writer.hpp"
#include "codegen/glsl_literal.hpp"
#include "expr/degree.hpp"

namespace zs {
namespace {

using Coeffs = std::vector<std::string>;  // GLSL names of c_0 .. c_k

std::string idx(const std::string& array, int i) { return array + "[" + std::to_string(i) + "]"; }

// A negative literal is parenthesized: "a * -2.0" is fine, "a - -2.0" lexes as a decrement.
std::string literal(double v) {
  const GlslLiteral lit = glslFloatLiteral(v);
  return lit.text.starts_with('-') ? "(" + lit.text + ")" : lit.text;
}

// A double literal with every digit a double has (the matrix entries of the double path).
std::string doubleLiteral(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17glf", v);
  std::string t = text;
  if (t.find_first_of(".e") == std::string::npos) t.insert(t.size() - 2, ".0");
  return v < 0 ? "(" + t + ")" : t;
}

double binomial(int n, int k) {
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

// Writes the truncated Taylor arithmetic of one body; every polynomial node gets its own
// temporaries "cN_k".
class TaylorWriter {
 public:
  TaylorWriter(const Graph& g, const std::vector<std::string>& names, int degree,
               const std::string& real)
      : g_(g), scalars_(g, names), names_(names), degree_(degree), real_(real) {}

  Coeffs node(NodeId id) {
    const Node& n = g_[id];
    switch (n.op) {
      case Op::VarX: return {"p.x", "v.x"};
      case Op::VarY: return {"p.y", "v.y"};
      case Op::VarZ: return {"p.z", "v.z"};
      case Op::Neg: {
        Coeffs r;
        for (const std::string& a : at(n.a)) r.push_back("-" + a);
        return declare(r);
      }
      case Op::Add: case Op::Sub: {
        const Coeffs &a = at(n.a), &b = at(n.b);
        Coeffs r(std::max(a.size(), b.size()));
        const char* op = n.op == Op::Add ? " + " : " - ";
        for (std::size_t i = 0; i < r.size(); ++i) {
          if (i < a.size() && i < b.size()) r[i] = a[i] + op + b[i];
          else if (i < a.size()) r[i] = a[i];
          else r[i] = n.op == Op::Add ? b[i] : "-" + b[i];
        }
        return declare(r);
      }
      case Op::Mul: return product(at(n.a), at(n.b));
      case Op::Div: {  // by an expression free of x, y, z (structuralDegrees allows no other)
        const std::string& b = names_[static_cast<std::size_t>(n.b)];
        const std::string inv = "c" + std::to_string(next_++) + "_inv";
        out += "  zs_u = zs_u || " + b + " == 0.0;\n";
        out += "  " + real_ + " " + inv + " = 1.0 / " + real_ + "(" + b + ");\n";
        Coeffs r;
        for (const std::string& a : at(n.a)) r.push_back(a + " * " + inv);
        return declare(r);
      }
      case Op::PowI: return power(at(n.a), n.ival);
      default: return {};  // not reached: every other opcode is spatially constant here
    }
  }

  void define(NodeId id) {
    if (g_.isSpatiallyConstant(id)) {
      scalars_.node(id, "zs_u");
      out += scalars_.out;
      scalars_.out.clear();
      coeffs_.emplace(id, Coeffs{names_[static_cast<std::size_t>(id)]});
      return;
    }
    coeffs_.emplace(id, node(id));
  }

  const Coeffs& at(NodeId id) const { return coeffs_.at(id); }

  std::string out;

 private:
  Coeffs declare(const Coeffs& exprs) {
    const std::string base = "c" + std::to_string(next_++) + "_";
    Coeffs names;
    for (std::size_t k = 0; k < exprs.size(); ++k) {
      names.push_back(base + std::to_string(k));
      out += "  " + real_ + " " + names.back() + " = " + exprs[k] + ";\n";
    }
    return names;
  }

  // Convolution truncated at the degree of F: coefficients past it cannot reach F.
  Coeffs product(const Coeffs& a, const Coeffs& b) {
    const int n = std::min<int>(int(a.size() + b.size()) - 1, degree_ + 1);
    Coeffs r(static_cast<std::size_t>(n));
    const bool square = a == b;
    for (int k = 0; k < n; ++k) {
      std::string sum, twice;
      for (int i = std::max(0, k - int(b.size()) + 1); i <= std::min(k, int(a.size()) - 1); ++i) {
        const int j = k - i;
        if (square && i > j) break;
        if (square && i < j) {
          twice += (twice.empty() ? "" : " + ") + a[i] + " * " + b[j];
        } else {
          sum += (sum.empty() ? "" : " + ") + a[i] + " * " + b[j];
        }
      }
      if (!twice.empty()) sum = "2.0 * (" + twice + ")" + (sum.empty() ? "" : " + " + sum);
      r[std::size_t(k)] = sum;
    }
    return declare(r);
  }

  Coeffs power(const Coeffs& a, int k) {
    if (k == 0) return {"1.0"};
    Coeffs result, square = a;
    for (int bits = k;;) {
      if (bits & 1) result = result.empty() ? square : product(result, square);
      bits >>= 1;
      if (bits == 0) break;
      square = product(square, square);
    }
    return result;
  }

  const Graph& g_;
  BodyWriter scalars_;
  const std::vector<std::string>& names_;
  int degree_;
  std::string real_;  // "float", or "double" where float would lose too much (header)
  int next_ = 0;
  std::unordered_map<NodeId, Coeffs> coeffs_;
};

std::string arrayParam(const std::string& name) { return "zs_Real " + name + "[zs_N]"; }

// de Casteljau rows at parameter `t` over the coefficients `in`; returns row j, entry i.
std::vector<std::vector<std::string>> deCasteljau(std::string& out, const std::string& prefix,
                                                  const Coeffs& in, const std::string& t) {
  const int d = int(in.size()) - 1;
  std::vector<std::vector<std::string>> rows{in};
  for (int j = 1; j <= d; ++j) {
    std::vector<std::string> row;
    for (int i = 0; i + j <= d; ++i) {
      row.push_back(prefix + std::to_string(j) + "_" + std::to_string(i));
      out += "  zs_Real " + row.back() + " = mix(" + rows[j - 1][i] + ", " + rows[j - 1][i + 1] +
             ", " + t + ");\n";
    }
    rows.push_back(row);
  }
  return rows;
}

Coeffs arrayNames(const std::string& array, int d) {
  Coeffs r;
  for (int i = 0; i <= d; ++i) r.push_back(idx(array, i));
  return r;
}

}  // namespace

std::optional<int> rayPolynomialDegree(const Graph& g, NodeId f) {
  const int d = structuralDegrees(g, f)[static_cast<std::size_t>(f)];
  return d >= 0 ? std::optional<int>(d) : std::nullopt;
}

std::string emitBernsteinKernelsGlsl(int d, bool doublePrecision) {
  std::string s;
  const std::string real = doublePrecision ? "double" : "float";
  s += "#define zs_Real " + real + "\n";
  s += std::string("#define zs_Real3 ") + (doublePrecision ? "dvec3" : "vec3") + "\n";
  s += std::string("#define zs_Real4 ") + (doublePrecision ? "dvec4" : "vec4") + "\n";
  // Unit roundoff of zs_Real, for the noise band of the isolation.
  s += std::string("const float zs_EPS = ") + (doublePrecision ? "1.2e-16" : "1.2e-7") + ";\n";
  s += "const int zs_DEGREE = " + std::to_string(d) + ";\n";
  s += "const int zs_N = " + std::to_string(d + 1) + ";\n";

  // c holds f in the power basis of s' = 2s - 1 in [-1, 1] (the expansion about the
  // segment's midpoint, whose coefficients stay far smaller than about an end). The
  // Bernstein coefficients of s'^j on [0, 1] are averages of +-1, so |b| <= sum |c|:
  //   b_i = sum_j c_j sum_k (-1)^(j-k) C(j, k) C(d-j, i-k) / C(d, i).
  s += "\nvoid zs_toBernstein(" + arrayParam("c") + ", out " + arrayParam("b") + ") {\n";
  for (int i = 0; i <= d; ++i) {
    std::string sum;
    for (int j = 0; j <= d; ++j) {
      double m = 0;
      for (int k = std::max(0, i - (d - j)); k <= std::min(i, j); ++k) {
        m += ((j - k) % 2 ? -1.0 : 1.0) * binomial(j, k) * binomial(d - j, i - k);
      }
      m /= binomial(d, i);
      if (m == 0) continue;
      const std::string factor = doublePrecision ? doubleLiteral(m) : literal(m);
      const std::string term = m == 1.0 ? idx("c", j) : factor + " * " + idx("c", j);
      sum += (sum.empty() ? "" : " + ") + term;
    }
    s += "  " + idx("b", i) + " = " + (sum.empty() ? "0.0" : sum) + ";\n";
  }
  s += "}\n";

  // Right part of the split at u ([u, 1]), then the left part of that at (w - u) / (1 - u).
  s += "\nvoid zs_restrict(" + arrayParam("b") + ", float u, float w, out " + arrayParam("r") + ") {\n";
  s += "  zs_Real t = zs_Real(u);\n";
  const auto right = deCasteljau(s, "e", arrayNames("b", d), "t");
  Coeffs tail;
  for (int k = 0; k <= d; ++k) tail.push_back(right[std::size_t(d - k)][std::size_t(k)]);
  s += "  zs_Real lambda = u < 1.0 ? zs_Real(w - u) / zs_Real(1.0 - u) : zs_Real(0.0);\n";
  const auto left = deCasteljau(s, "h", tail, "lambda");
  for (int k = 0; k <= d; ++k) s += "  " + idx("r", k) + " = " + left[std::size_t(k)][0] + ";\n";
  s += "}\n";

  // Horner on the power basis (the Taylor coefficients themselves, not a conversion of them):
  // f, f' and f''/2 at s' in [-1, 1] in 3D multiply-adds, for the refinement of an isolated
  // root (Halley's method).
  s += "\nvec3 zs_powerAt(" + arrayParam("c") + ", zs_Real x) {\n";
  s += "  zs_Real f = " + idx("c", d) + ", df = 0.0, h = 0.0;\n";
  for (int k = d - 1; k >= 0; --k) {
    s += "  h = h * x + df; df = df * x + f; f = f * x + " + idx("c", k) + ";\n";
  }
  s += "  return vec3(f, df, h);\n}\n\n";

  s += "\nzs_Real zs_maxAbs(" + arrayParam("b") + ") {\n  zs_Real m = abs(" + idx("b", 0) + ");\n";
  for (int i = 1; i <= d; ++i) s += "  m = max(m, abs(" + idx("b", i) + "));\n";
  s += "  return m;\n}\n";

  // Where the control polygon first crosses 0 (in [0, 1]): the start of the refinement of an
  // isolated root, far nearer to it than the chord of the ends when f bends. Scanned from the
  // right so the leftmost crossing wins; one division.
  s += "\nfloat zs_firstCrossing(" + arrayParam("b") + ") {\n";
  s += "  zs_Real bi = " + idx("b", 0) + ", bj = " + idx("b", 1) + ";\n  float i = 0.0;\n";
  for (int i = d - 1; i >= 0; --i) {
    s += "  if ((" + idx("b", i) + " > 0.0) != (" + idx("b", i + 1) + " > 0.0)) { bi = " +
         idx("b", i) + "; bj = " + idx("b", i + 1) + "; i = " + std::to_string(i) + ".0; }\n";
  }
  s += "  return clamp((i + (bi != bj ? float(bi / (bi - bj)) : 0.0)) / float(zs_DEGREE), 0.0, 1.0);\n}\n";

  // Sign changes count b_i > 0 against b_i <= 0, so a zero coefficient never hides a root:
  // the hull test (min, max) decides emptiness, the counts only decide when to stop.
  s += "\nzs_Real4 zs_classify(" + arrayParam("b") + ") {\n";
  s += "  zs_Real lo = " + idx("b", 0) + ", hi = " + idx("b", 0) + ", v = 0.0, dv = 0.0;\n";
  for (int i = 1; i <= d; ++i) {
    s += "  lo = min(lo, " + idx("b", i) + "); hi = max(hi, " + idx("b", i) + ");\n";
    s += "  v += zs_Real((" + idx("b", i - 1) + " > 0.0) != (" + idx("b", i) + " > 0.0));\n";
  }
  for (int i = 1; i < d; ++i) {
    s += "  dv += zs_Real((" + idx("b", i) + " > " + idx("b", i - 1) + ") != (" + idx("b", i + 1) +
         " > " + idx("b", i) + "));\n";
  }
  s += "  return zs_Real4(lo, hi, v, dv);\n}\n";
  return s;
}

std::optional<RayPolynomialGlsl> emitRayPolynomialGlsl(const Graph& g, NodeId f) {
  const std::optional<int> degree = rayPolynomialDegree(g, f);
  if (!degree) return std::nullopt;
  const int d = *degree;
  const std::vector<NodeId> order = reachable(g, {f});
  const std::vector<std::string> names = nameNodes(g, order);

  RayPolynomialGlsl result;
  result.degree = d;
  std::string& s = result.source;
  s += "// zeroset ray polynomial (generated by src/codegen/emit_ray_polynomial.cpp): f(s) =\n";
  s += "// F(p + s v) of degree " + std::to_string(d) + " and its Bernstein kernels.\n";
  s += emitBernsteinKernelsGlsl(d, d >= kDoubleDegree);

  result.doublePrecision = d >= kDoubleDegree;
  TaylorWriter taylor(g, names, d, result.doublePrecision ? "double" : "float");
  for (NodeId id : order) taylor.define(id);
  s += "\n// Coefficients of f(s) in the power basis; false where F is undefined on the whole ray.\n";
  s += "bool zs_FPoly(zs_Real3 p, zs_Real3 v, out zs_Real c[zs_N]) {\n";
  s += "  bool zs_u = false;\n";
  s += taylor.out;
  const Coeffs& root = taylor.at(f);
  for (int k = 0; k <= d; ++k) {
    s += "  " + idx("c", k) + " = " + (k < int(root.size()) ? root[std::size_t(k)] : "0.0") + ";\n";
  }
  s += "  return !zs_u;\n}\n";
  return result;
}

}  // namespace zs
