#include "codegen/emit_ray_polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string_view>
#include <vector>

#include "codegen/body_writer.hpp"
#include "expr/degree.hpp"

namespace zs {
namespace {

using Coeffs = std::vector<std::string>;  // GLSL names of c_0 .. c_k

std::string idx(const std::string& array, int i) {
  return array + "[" + std::to_string(i) + "]";
}

// A double literal with every digit a double has (the conversion matrix's entries); a
// negative one is parenthesized: "a * -2.0" is fine, "a - -2.0" lexes as a decrement.
std::string doubleLiteral(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17glf", v);
  std::string t = text;
  if (t.find_first_of(".e") == std::string::npos) t.insert(t.size() - 2, ".0");
  return v < 0 ? "(" + t + ")" : t;
}

// The float at or above v, as a literal: a factor that may only overestimate.
std::string roundedUpLiteral(double v) {
  float f = float(v);
  if (double(f) < v) f = std::nextafter(f, INFINITY);
  char text[40];
  std::snprintf(text, sizeof text, "%.9g", double(f));
  std::string t = text;
  if (t.find_first_of(".e") == std::string::npos) t += ".0";
  return t;
}

// How often `what` occurs in `text`.
std::size_t occurrences(const std::string& text, std::string_view what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The expansion's arithmetic as GLSL text: the operators of double (fp64), or calls to the
// double-float functions of kDoubleFloatGlsl (GLSL ES: a value is a vec2 hi + lo).
struct WideOps {
  bool df = false;
  // Products of at least this many terms as calls of zs_dfConvolve (a loop) instead of
  // written out term by term; 0: none.
  int loopTerms = 0;
  std::string add(const std::string& a, const std::string& b) const {
    return df ? "zs_dfAdd(" + a + ", " + b + ")" : a + " + " + b;
  }
  std::string sub(const std::string& a, const std::string& b) const {
    return df ? "zs_dfAdd(" + a + ", -(" + b + "))" : a + " - " + b;
  }
  std::string neg(const std::string& a) const { return df ? "(-" + a + ")" : "-" + a; }
  std::string mul(const std::string& a, const std::string& b) const {
    return df ? "zs_dfMul(" + a + ", " + b + ")" : a + " * " + b;
  }
  // A float value (a constant of the formula block) as a wide one.
  std::string widen(const std::string& a) const {
    return df ? "vec2(" + a + ", 0.0)" : "zs_Wide(" + a + ")";
  }
  // |x| of a wide value, as the bound's type (float in double-float, whose bound is float).
  std::string absOf(const std::string& a) const {
    return df ? "abs(" + a + ".x)" : "abs(" + a + ")";
  }
};

// The double-float arithmetic of GLSL ES (no double, no fma): Knuth's two-sum and Dekker's
// split and two-product give each operation's rounding error exactly, so a value carries
// about 44 bits. Each operation errs by at most zs_WIDE_EPS times its operands' magnitude.
constexpr const char* kDoubleFloatGlsl = R"glsl(
vec2 zs_twoSum(float a, float b) {
  float s = a + b, v = s - a;
  return vec2(s, (a - (s - v)) + (b - v));
}
vec2 zs_fastTwoSum(float a, float b) {
  float s = a + b;
  return vec2(s, b - (s - a));
}
vec2 zs_split(float a) {
  float t = 4097.0 * a;
  float hi = t - (t - a);
  return vec2(hi, a - hi);
}
vec2 zs_twoProd(float a, float b) {
  float p = a * b;
  vec2 as = zs_split(a), bs = zs_split(b);
  return vec2(p, ((as.x * bs.x - p) + as.x * bs.y + as.y * bs.x) + as.y * bs.y);
}
vec2 zs_dfAdd(vec2 a, vec2 b) {
  vec2 s = zs_twoSum(a.x, b.x), t = zs_twoSum(a.y, b.y);
  s = zs_fastTwoSum(s.x, s.y + t.x);
  return zs_fastTwoSum(s.x, s.y + t.y);
}
vec2 zs_dfMul(vec2 a, vec2 b) {
  vec2 p = zs_twoProd(a.x, b.x);
  return zs_fastTwoSum(p.x, p.y + (a.x * b.y + a.y * b.x));
}
vec2 zs_dfDiv(vec2 a, vec2 b) {
  float q1 = a.x / b.x;
  vec2 r = zs_dfAdd(a, -zs_dfMul(vec2(q1, 0.0), b));
  float q2 = r.x / b.x;
  r = zs_dfAdd(r, -zs_dfMul(vec2(q2, 0.0), b));
  return zs_dfAdd(zs_fastTwoSum(q1, q2), vec2(r.x / b.x, 0.0));
}
)glsl";

// A double as a double-float literal: its float and the float of the rest.
std::string dfLiteral(double v) {
  const float hi = float(v);
  const float lo = float(v - double(hi));
  char text[80];
  std::snprintf(text, sizeof text, "vec2(%.9g, %.9g)", double(hi), double(lo));
  return text;
}

double binomial(int n, int k) {
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

// Writes the truncated Taylor arithmetic of one body, in zs_Wide; every polynomial node gets
// its own temporaries "cN_k". Beside them it writes, per node, the scalar "aN": the same expression
// evaluated with every operation on absolute values at |p| + |v| (so aN >= sum_k |cN_k| in
// exact arithmetic), and it counts the roundings n on the longest path to each coefficient.
// Together they bound the rounding error of every computed coefficient a priori: |c_k - exact|
// <= gamma_n sum_k |exact terms| <= n u aN (the standard bound for sums of products, Higham
// ch. 3), the rigorous noise band of the isolation (raytrace_bernstein.frag.glsl).
class TaylorWriter {
 public:
  TaylorWriter(const Graph& g, const std::vector<std::string>& names, int degree, WideOps ops)
      : g_(g), scalars_(g, names), names_(names), degree_(degree), ops_(ops) {}

  Coeffs node(NodeId id) {
    const Node& n = g_[id];
    switch (n.op) {
      case Op::VarX:
      case Op::VarY:
      case Op::VarZ: {
        const std::string axis = n.op == Op::VarX ? "x" : n.op == Op::VarY ? "y" : "z";
        if (ops_.df) {
          bound(id, "abs(p" + axis + ".x) + abs(v" + axis + ".x)", 0);
          return {"p" + axis, "v" + axis};
        }
        bound(id, "abs(p." + axis + ") + abs(v." + axis + ")", 0);
        return {"p." + axis, "v." + axis};
      }
      case Op::Neg: {
        Coeffs r;
        for (const std::string& a : at(n.a)) r.push_back(ops_.neg(a));
        bound(id, boundOf(n.a), roundingsOf(n.a));
        return declare(r);
      }
      case Op::Add:
      case Op::Sub: {
        const Coeffs &a = at(n.a), &b = at(n.b);
        Coeffs r(std::max(a.size(), b.size()));
        for (std::size_t i = 0; i < r.size(); ++i) {
          if (i < a.size() && i < b.size())
            r[i] = n.op == Op::Add ? ops_.add(a[i], b[i]) : ops_.sub(a[i], b[i]);
          else if (i < a.size())
            r[i] = a[i];
          else
            r[i] = n.op == Op::Add ? b[i] : ops_.neg(b[i]);
        }
        bound(id, boundOf(n.a) + " + " + boundOf(n.b),
              std::max(roundingsOf(n.a), roundingsOf(n.b)) + 1);
        return declare(r);
      }
      case Op::Mul:
        bound(id, boundOf(n.a) + " * " + boundOf(n.b),
              roundingsOf(n.a) + roundingsOf(n.b) + productRoundings(at(n.a), at(n.b)));
        return product(at(n.a), at(n.b));
      case Op::Div: {  // by an expression free of x, y, z (structuralDegrees allows no other)
        const std::string& b = names_[static_cast<std::size_t>(n.b)];
        const std::string inv = "c" + std::to_string(next_++) + "_inv";
        out += "  zs_u = zs_u || " + b + " == 0.0;\n";
        out += "  zs_Wide " + inv + " = " +
               (ops_.df ? "zs_dfDiv(vec2(1.0, 0.0), vec2(" + b + ", 0.0))"
                        : "1.0 / zs_Wide(" + b + ")") +
               ";\n";
        Coeffs r;
        for (const std::string& a : at(n.a)) r.push_back(ops_.mul(a, inv));
        bound(id, boundOf(n.a) + " * " + ops_.absOf(inv), roundingsOf(n.a) + roundingsOf(n.b) + 2);
        return declare(r);
      }
      case Op::PowI:
        return power(id, at(n.a), n.ival);
      default:
        return {};  // not reached: every other opcode is spatially constant here
    }
  }

  void define(NodeId id) {
    if (g_.isSpatiallyConstant(id)) {
      scalars_.node(id, "zs_u");
      out += scalars_.out;
      scalars_.out.clear();
      const std::string& name = names_[static_cast<std::size_t>(id)];
      coeffs_.emplace(id, Coeffs{ops_.df ? ops_.widen(name) : name});
      bound(id, ops_.df ? "abs(" + name + ")" : "abs(zs_Wide(" + name + "))",
            constantRoundings(id));
      return;
    }
    coeffs_.emplace(id, node(id));
  }

  const Coeffs& at(NodeId id) const { return coeffs_.at(id); }
  const std::string& boundOf(NodeId id) const { return bounds_.at(id); }
  int roundingsOf(NodeId id) const { return roundings_.at(id); }

  std::string out;

 private:
  Coeffs declare(const Coeffs& exprs) {
    const std::string base = "c" + std::to_string(next_++) + "_";
    Coeffs names;
    for (std::size_t k = 0; k < exprs.size(); ++k) {
      names.push_back(base + std::to_string(k));
      out += "  zs_Wide " + names.back() + " = " + exprs[k] + ";\n";
    }
    return names;
  }

  // Convolution truncated at the degree of F: coefficients past it cannot reach F.
  Coeffs product(const Coeffs& a, const Coeffs& b) {
    const int n = std::min<int>(int(a.size() + b.size()) - 1, degree_ + 1);
    if (ops_.loopTerms > 0) {
      int terms = 0;
      for (int k = 0; k < n; ++k)
        terms += std::min(k, int(a.size()) - 1) - std::max(0, k - int(b.size()) + 1) + 1;
      if (terms >= ops_.loopTerms) return loopProduct(a, b, n);
    }
    Coeffs r(static_cast<std::size_t>(n));
    const bool square = a == b;
    for (int k = 0; k < n; ++k) {
      std::string sum, twice;
      for (int i = std::max(0, k - int(b.size()) + 1); i <= std::min(k, int(a.size()) - 1); ++i) {
        const int j = k - i;
        if (square && i > j) break;
        std::string& into = square && i < j ? twice : sum;
        into = into.empty() ? ops_.mul(a[i], b[j]) : ops_.add(into, ops_.mul(a[i], b[j]));
      }
      // Doubling is exact in either arithmetic.
      if (!twice.empty())
        sum = sum.empty() ? "2.0 * (" + twice + ")" : ops_.add("2.0 * (" + twice + ")", sum);
      r[std::size_t(k)] = sum;
    }
    return declare(r);
  }

  // The same convolution by zs_dfConvolve, which sums each coefficient's products in
  // ascending order from zero (an exact first addition): no more roundings on any path than
  // the sum written out (productRoundings), so the same bound holds.
  Coeffs loopProduct(const Coeffs& a, const Coeffs& b, int n) {
    const std::string name = "c" + std::to_string(next_++);
    const auto constructor = [&](const Coeffs& c) {
      std::string t = "vec2[zs_N](";
      for (int k = 0; k <= degree_; ++k)
        t += (k ? ", " : "") + (k < int(c.size()) ? c[std::size_t(k)] : std::string("vec2(0.0)"));
      return t + ")";
    };
    out += "  vec2 " + name + "[zs_N];\n";
    out += "  zs_dfConvolve(" + constructor(a) + ", " + std::to_string(a.size()) + ", " +
           constructor(b) + ", " + std::to_string(b.size()) + ", " + std::to_string(n) + ", " +
           name + ");\n";
    Coeffs r;
    for (int k = 0; k < n; ++k) r.push_back(name + "[" + std::to_string(k) + "]");
    return r;
  }

  // Roundings a convolution adds to its factors' own: one per product, and the longest sum.
  static int productRoundings(const Coeffs& a, const Coeffs& b) {
    return int(std::min(a.size(), b.size()));
  }

  // The bound and rounding count of a product node are those of the squaring chain below.
  Coeffs power(NodeId id, const Coeffs& a, int k) {
    const NodeId base = g_[id].a;
    if (k == 0) {
      bound(id, "1.0", 0);
      return {ops_.df ? "vec2(1.0, 0.0)" : "1.0"};
    }
    Coeffs result, square = a;
    std::string resultBound, squareBound = boundOf(base);
    int resultRoundings = 0, squareRoundings = roundingsOf(base);
    for (int bits = k;;) {
      if (bits & 1) {
        if (result.empty()) {
          result = square, resultBound = squareBound, resultRoundings = squareRoundings;
        } else {
          resultRoundings += squareRoundings + productRoundings(result, square);
          resultBound = declareBound(resultBound + " * " + squareBound);
          result = product(result, square);
        }
      }
      bits >>= 1;
      if (bits == 0) break;
      squareRoundings += squareRoundings + productRoundings(square, square);
      squareBound = declareBound(squareBound + " * " + squareBound);
      square = product(square, square);
    }
    bound(id, resultBound, resultRoundings);
    return result;
  }

  // Roundings of a value free of x, y, z computed in the shader's float: a few per level of
  // its subexpression (library functions are not correctly rounded), counted generously.
  int constantRoundings(NodeId id) {
    if (auto it = constantRoundings_.find(id); it != constantRoundings_.end()) return it->second;
    const Node& n = g_[id];
    int below = 0;
    if (n.a != kNoNode) below = std::max(below, constantRoundings(n.a));
    if (n.b != kNoNode) below = std::max(below, constantRoundings(n.b));
    const int r = below + (n.op == Op::Const || n.op == Op::Param ? 1 : 4);
    constantRoundings_.emplace(id, r);
    return r;
  }

  std::string declareBound(const std::string& expr) {
    const std::string name = "a" + std::to_string(next_++);
    out += "  zs_Bound " + name + " = " + expr + ";\n";
    return name;
  }

  void bound(NodeId id, const std::string& expr, int roundings) {
    bounds_[id] = declareBound(expr);
    roundings_[id] = roundings;
  }

  const Graph& g_;
  BodyWriter scalars_;
  const std::vector<std::string>& names_;
  int degree_;
  WideOps ops_;
  int next_ = 0;
  std::unordered_map<NodeId, Coeffs> coeffs_;
  std::unordered_map<NodeId, std::string> bounds_;
  std::unordered_map<NodeId, int> roundings_, constantRoundings_;
};

std::string arrayParam(const std::string& name) {
  return "zs_Real " + name + "[zs_N]";
}

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

std::string emitBernsteinKernelsGlsl(int d, bool doublePrecision, bool fp64) {
  doublePrecision = doublePrecision && fp64;
  std::string s;
  const std::string real = doublePrecision ? "double" : "float";
  s += "#define zs_Real " + real + "\n";
  // The expansion's type: double where the GPU has it, double-float (vec2) in GLSL ES
  // (WebGL2); the bound's: double, or float (it only scales the noise band).
  s += std::string("#define zs_Wide ") + (fp64 ? "double" : "vec2") + "\n";
  s += std::string("#define zs_Bound ") + (fp64 ? "double" : "float") + "\n";
  // Twice the unit roundoff (2^-23 of float, 2^-52 of double): the noise band of the
  // isolation is a first-order bound; the factor 2 covers the rest and its own rounding.
  s += std::string("const zs_Real zs_EPS = ") + (doublePrecision ? "2.23e-16lf" : "1.2e-7") + ";\n";
  // Double-float: 2^-44, over twice its operations' error bounds (about 3u^2 for an addition
  // and 7u^2 for a product, u = 2^-24), which also covers the bound's own rounding in float.
  s += std::string("const zs_Bound zs_WIDE_EPS = ") + (fp64 ? "2.23e-16lf" : "5.7e-14") + ";\n";
  // Double-float's low parts flush to zero below float's normal range, where its error is
  // no longer relative: an absolute floor on the noise band (0 with double).
  s += std::string("const zs_Real zs_NOISE_FLOOR = ") + (fp64 ? "0.0" : "1e-36") + ";\n";
  if (!fp64) s += kDoubleFloatGlsl;
  s += "const int zs_DEGREE = " + std::to_string(d) + ";\n";
  s += "const int zs_N = " + std::to_string(d + 1) + ";\n";

  // c holds f in the power basis of s' = 2s - 1 in [-1, 1] (the expansion about the
  // segment's midpoint, whose coefficients stay far smaller than about an end). The
  // Bernstein coefficients of s'^j on [0, 1] are averages of +-1, so |b| <= sum |c|:
  //   b_i = sum_j c_j sum_k (-1)^(j-k) C(j, k) C(d-j, i-k) / C(d, i).
  // Computed in zs_Wide from the expansion, then rounded once to zs_Real; `narrow` gets the
  // power coefficients rounded once too, for the refinement's Horner steps.
  s += "\nvoid zs_toBernstein(zs_Wide c[zs_N], out zs_Real b[zs_N], out zs_Real narrow[zs_N]) {\n";
  for (int i = 0; i <= d; ++i) {
    std::string sum;
    for (int j = 0; j <= d; ++j) {
      double m = 0;
      for (int k = std::max(0, i - (d - j)); k <= std::min(i, j); ++k) {
        m += ((j - k) % 2 ? -1.0 : 1.0) * binomial(j, k) * binomial(d - j, i - k);
      }
      m /= binomial(d, i);
      if (m == 0) continue;
      if (fp64) {
        const std::string term = m == 1.0 ? idx("c", j) : doubleLiteral(m) + " * " + idx("c", j);
        sum += (sum.empty() ? "" : " + ") + term;
      } else {
        const std::string term =
            m == 1.0 ? idx("c", j) : "zs_dfMul(" + dfLiteral(m) + ", " + idx("c", j) + ")";
        sum = sum.empty() ? term : "zs_dfAdd(" + sum + ", " + term + ")";
      }
    }
    if (fp64) {
      s += "  " + idx("b", i) + " = zs_Real(" + (sum.empty() ? "0.0" : sum) + ");\n";
      s += "  " + idx("narrow", i) + " = zs_Real(" + idx("c", i) + ");\n";
    } else {  // hi + lo rounded once
      s += "  { vec2 t = " + (sum.empty() ? std::string("vec2(0.0)") : sum) + "; " + idx("b", i) +
           " = t.x + t.y; }\n";
      s += "  " + idx("narrow", i) + " = " + idx("c", i) + ".x + " + idx("c", i) + ".y;\n";
    }
  }
  s += "}\n";

  // One de Casteljau pass at lambda: f on [0, lambda] and on [lambda, 1]. The isolation's walk
  // keeps f on the rest of its window, so each of its steps is one pass (docs/renderer.md).
  s += "\nvoid zs_split(" + arrayParam("b") + ", zs_Real lambda, out " + arrayParam("left") +
       ", out " + arrayParam("right") + ") {\n";
  const auto rows = deCasteljau(s, "e", arrayNames("b", d), "lambda");
  for (int k = 0; k <= d; ++k) {
    s += "  " + idx("left", k) + " = " + rows[std::size_t(k)][0] + ";\n";
    s += "  " + idx("right", k) + " = " + rows[std::size_t(d - k)][std::size_t(k)] + ";\n";
  }
  s += "}\n";
  // b = next where `take`, element by element (constant indices).
  s += "\nvoid zs_take(inout " + arrayParam("b") + ", " + arrayParam("next") + ", bool take) {\n";
  for (int k = 0; k <= d; ++k) {
    s += "  " + idx("b", k) + " = take ? " + idx("next", k) + " : " + idx("b", k) + ";\n";
  }
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
    s += "  if ((" + idx("b", i) + " > 0.0) != (" + idx("b", i + 1) +
         " > 0.0)) { bi = " + idx("b", i) + "; bj = " + idx("b", i + 1) +
         "; i = " + std::to_string(i) + ".0; }\n";
  }
  s += "  return clamp((i + (bi != bj ? float(bi / (bi - bj)) : 0.0)) / float(zs_DEGREE), 0.0, "
       "1.0);\n}\n";

  // How much of [0, 1] at each end is proven to keep f beyond a band |f| < band, given
  // lim = band + noise (every exact coefficient within noise of b_i): by the supporting line
  // of the control points at that end. At the start, for b_0 > lim, the control points lie
  // on or above b_0 - m t with m = max_i (b_0 - b_i) d / i, so f > band for t < (b_0 - lim)
  // / m (mirrored for b_0 < -lim, and at the end). 0 at an end that may lie in the band;
  // shrunk by 1e-5 for the rounding of its own arithmetic (a volume's skipped steps,
  // raytrace_volume.frag.glsl).
  s += "\nvec2 zs_clearEnds(" + arrayParam("b") + ", zs_Real lim) {\n";
  s += "  zs_Real s0 = " + idx("b", 0) + " > 0.0 ? 1.0 : -1.0, h0 = s0 * " + idx("b", 0) +
       " - lim, m0 = 0.0;\n";
  s += "  zs_Real s1 = " + idx("b", d) + " > 0.0 ? 1.0 : -1.0, h1 = s1 * " + idx("b", d) +
       " - lim, m1 = 0.0;\n";
  const auto slope = [&](const std::string& sign, int from, int i, int steps) {
    const std::string diff = sign + " * (" + idx("b", from) + " - " + idx("b", i) + ")";
    return steps == d ? diff : diff + " * " + roundedUpLiteral(double(d) / double(steps));
  };
  for (int i = 1; i <= d; ++i) s += "  m0 = max(m0, " + slope("s0", 0, i, i) + ");\n";
  for (int i = 0; i < d; ++i) s += "  m1 = max(m1, " + slope("s1", d, i, d - i) + ");\n";
  s += "  return vec2(h0 > 0.0 ? (m0 > h0 ? float(h0 / m0) * 0.99999 : 1.0) : 0.0,\n"
       "              h1 > 0.0 ? (m1 > h1 ? float(h1 / m1) * 0.99999 : 1.0) : 0.0);\n}\n";

  // The isolation's tests, counted in int rather than taken from the extremes (llvmpipe
  // builds min and max of doubles with NaN tests and a split of the vector, and && chains
  // slowed its loop too): (1 when every coefficient lies above noise, -1 when every one lies
  // below -noise, else 0; 1 when every one lies within [-noise, noise]; the sign changes V
  // of b; those of its differences). A NaN coefficient (overflow) counts as above and below:
  // such an interval proves nothing and is passed over. Sign changes count b_i > 0 against
  // b_i <= 0, so a zero coefficient never hides a root: the band tests decide emptiness, the
  // counts only decide when to stop.
  s += "\nivec4 zs_bands(" + arrayParam("b") + ", zs_Real noise) {\n  int above = 0, below = 0;\n";
  for (int i = 0; i <= d; ++i) {
    const std::string bi = idx("b", i);
    s += "  above += int(!(" + bi + " <= noise)); below += int(!(" + bi + " >= -noise));\n";
  }
  s += "  int v = 0, dv = 0;\n  bool p0 = " + idx("b", 0) + " > 0.0;\n";
  for (int i = 1; i <= d; ++i) {
    const std::string bi = idx("b", i), n = std::to_string(i), m = std::to_string(i - 1);
    s += "  bool p" + n + " = " + bi + " > 0.0; v += int(p" + m + " != p" + n + ");\n";
    s += "  bool g" + n + " = " + bi + " > " + idx("b", i - 1) + ";\n";
    if (i >= 2) s += "  dv += int(g" + m + " != g" + n + ");\n";
  }
  s += "  return ivec4(above == zs_N ? 1 : (below == zs_N ? -1 : 0), int(above + below == 0), v, "
       "dv);\n}\n";

  // The least and largest coefficient (a volume's bound on f), by selects (a NaN b_i after
  // b_0 fails both comparisons and is passed over; a NaN b_0 stays in both).
  s += "\nvoid zs_extremes(" + arrayParam("b") + ", out zs_Real lo, out zs_Real hi) {\n";
  s += "  lo = " + idx("b", 0) + ";\n  hi = " + idx("b", 0) + ";\n";
  for (int i = 1; i <= d; ++i) {
    const std::string bi = idx("b", i);
    s += "  lo = " + bi + " < lo ? " + bi + " : lo; hi = " + bi + " > hi ? " + bi + " : hi;\n";
  }
  s += "}\n";
  return s;
}

std::optional<RayPolynomialGlsl> emitRayPolynomialGlsl(const Graph& g, NodeId f, bool fp64,
                                                       DoubleFloatLoops loops) {
  const std::optional<int> degree = rayPolynomialDegree(g, f);
  if (!degree) return std::nullopt;
  // A constant F is traced as a polynomial of degree 1 whose slope is 0: the kernels need
  // two coefficients, and the isolation then finds no root (or, for F = 0, every point).
  const int d = std::max(*degree, 1);
  const std::vector<NodeId> order = reachable(g, {f});
  const std::vector<std::string> names = nameNodes(g, order);

  RayPolynomialGlsl result;
  result.degree = d;
  std::string& s = result.source;
  s += "// zeroset ray polynomial (generated by src/codegen/emit_ray_polynomial.cpp): f(s) =\n";
  s += "// F(p + s v) of degree " + std::to_string(d) + " and its Bernstein kernels.\n";
  result.fp64 = fp64;
  result.doublePrecision = fp64 && d >= kDoubleDegree;
  s += emitBernsteinKernelsGlsl(d, result.doublePrecision, fp64);

  WideOps ops;
  ops.df = !fp64;
  std::optional<TaylorWriter> written;
  const auto write = [&] {
    written.emplace(g, names, d, ops);
    for (NodeId id : order) written->define(id);
  };
  write();
  if (ops.df && occurrences(written->out, "zs_dfMul(") > std::size_t(std::max(loops.products, 0))) {
    ops.loopTerms = std::max(loops.terms, 1);  // written anew with its long convolutions as loops
    write();
  }
  TaylorWriter& taylor = *written;
  // The rounding count of the coefficients, plus that of the conversion to Bernstein form
  // (d + 1 products summed, the matrix entries rounded once).
  s += "\n// Roundings on the longest path to a Bernstein coefficient in zs_Wide (zs_FPoly's "
       "error\n";
  s += "// bound, with the conversion's d + 1 products summed).\n";
  s += "const zs_Bound zs_ROUNDINGS = " + std::to_string(taylor.roundingsOf(f) + d + 3) + ".0;\n";
  if (ops.loopTerms > 0) {
    s += "\n// r_k = sum_i a_i b_(k-i) for k < n, in double-float, i ascending.\n"
         "void zs_dfConvolve(vec2 a[zs_N], int na, vec2 b[zs_N], int nb, int n, out vec2 r[zs_N]) "
         "{\n"
         "  for (int k = 0; k < zs_N; ++k) {\n"
         "    vec2 sum = vec2(0.0);\n"
         "    for (int i = max(0, k - nb + 1); i <= min(k, na - 1) && k < n; ++i)\n"
         "      sum = zs_dfAdd(sum, zs_dfMul(a[i], b[k - i]));\n"
         "    r[k] = sum;\n"
         "  }\n"
         "}\n";
  }
  s += "\n// Coefficients of f(s) in the power basis, in zs_Wide, and `bound` >= sum_k |c_k| "
       "computed\n";
  s += "// with every operation on absolute values: the error of any Bernstein coefficient made\n";
  s += "// from them in zs_Wide is at most zs_ROUNDINGS zs_WIDE_EPS bound. False where F is\n";
  s += "// undefined on the whole ray.\n";
  if (fp64) {
    s += "bool zs_FPoly(dvec3 p, dvec3 v, out zs_Wide c[zs_N], out zs_Bound bound) {\n";
  } else {
    s += "bool zs_FPoly(vec2 px, vec2 py, vec2 pz, vec2 vx, vec2 vy, vec2 vz, out zs_Wide "
         "c[zs_N],\n";
    s += "              out zs_Bound bound) {\n";
  }
  s += "  bool zs_u = false;\n";
  s += taylor.out;
  const Coeffs& root = taylor.at(f);
  for (int k = 0; k <= d; ++k) {
    s += "  " + idx("c", k) + " = " +
         (k < int(root.size()) ? root[std::size_t(k)] : std::string(fp64 ? "0.0" : "vec2(0.0)")) +
         ";\n";
  }
  s += "  bound = " + taylor.boundOf(f) + ";\n";
  s += "  return !zs_u;\n}\n";
  // The segment [wa, wb] of the ray o + t d: its midpoint and half of it, in the wide type.
  s += "\n// f on the ray segment [wa, wb] of o + t d, expanded about the segment's midpoint.\n";
  s += "bool zs_FPolyOn(vec3 o, vec3 d, float wa, float wb, out zs_Wide c[zs_N], out zs_Bound "
       "bound) {\n";
  if (fp64) {
    s += "  return zs_FPoly(dvec3(o) + (0.5 * (double(wa) + double(wb))) * dvec3(d),\n";
    s += "                  (0.5 * double(wb - wa)) * dvec3(d), c, bound);\n}\n";
  } else {
    s += "  vec2 mid = 0.5 * zs_twoSum(wa, wb), halfLen = vec2(0.5 * (wb - wa), 0.0);\n";
    s += "  return zs_FPoly(zs_dfAdd(vec2(o.x, 0.0), zs_dfMul(mid, vec2(d.x, 0.0))),\n";
    s += "                  zs_dfAdd(vec2(o.y, 0.0), zs_dfMul(mid, vec2(d.y, 0.0))),\n";
    s += "                  zs_dfAdd(vec2(o.z, 0.0), zs_dfMul(mid, vec2(d.z, 0.0))),\n";
    s +=
        "                  zs_dfMul(halfLen, vec2(d.x, 0.0)), zs_dfMul(halfLen, vec2(d.y, 0.0)),\n";
    s += "                  zs_dfMul(halfLen, vec2(d.z, 0.0)), c, bound);\n}\n";
  }
  return result;
}

}  // namespace zs
