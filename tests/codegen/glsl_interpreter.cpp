#include "glsl_interpreter.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <unordered_map>

namespace zs::test {
namespace {

constexpr float kFltMax = 3.4028235e38f;

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string_view::npos) return "";
  const auto e = s.find_last_not_of(' ');
  return std::string(s.substr(b, e - b + 1));
}

// The statements between "<signature> {" and the closing "}" line, comments removed.
std::vector<std::string> functionBody(std::string_view block, std::string_view signature) {
  const auto start = block.find(std::string(signature) + " {\n");
  if (start == std::string_view::npos) throw std::runtime_error("no " + std::string(signature));
  std::vector<std::string> lines;
  std::size_t pos = block.find('\n', start) + 1;
  while (pos < block.size()) {
    const std::size_t end = block.find('\n', pos);
    std::string_view line = block.substr(pos, end - pos);
    pos = end + 1;
    if (line == "}") return lines;
    if (auto c = line.find("//"); c != std::string_view::npos) line = line.substr(0, c);
    lines.push_back(trim(line));
  }
  throw std::runtime_error("unterminated " + std::string(signature));
}

std::vector<std::string> splitArgs(std::string_view s) {
  std::vector<std::string> out;
  std::size_t depth = 0, begin = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '(') ++depth;
    if (s[i] == ')') --depth;
    if (s[i] == ',' && depth == 0) {
      out.push_back(trim(s.substr(begin, i - begin)));
      begin = i + 1;
    }
  }
  out.push_back(trim(s.substr(begin)));
  return out;
}

struct Machine {
  std::array<float, 3> p;
  std::span<const float> params;
  std::unordered_map<std::string, float> vars;
  std::unordered_map<std::string, bool> flags;

  float operand(const std::string& s) const {
    if (s.empty()) throw std::runtime_error("empty operand");
    if (s.front() == '(' && s.back() == ')') return operand(s.substr(1, s.size() - 2));
    if (s == "p.x") return p[0];
    if (s == "p.y") return p[1];
    if (s == "p.z") return p[2];
    if (s.rfind("zs_params[", 0) == 0) return params[std::stoul(s.substr(10))];
    if (s.front() == '-' || s.front() == '.' || (s.front() >= '0' && s.front() <= '9')) {
      return static_cast<float>(std::strtod(s.c_str(), nullptr));  // as glslang reads it
    }
    auto it = vars.find(s);
    if (it == vars.end()) throw std::runtime_error("unknown operand '" + s + "'");
    return it->second;
  }

  bool& flag(const std::string& name) {
    auto it = flags.find(name);
    if (it == flags.end()) throw std::runtime_error("unknown flag '" + name + "'");
    return it->second;
  }

  // Models of the GLSL built-ins and prelude helpers, in float.
  float call(const std::string& fn, const std::vector<std::string>& args) {
    auto arg = [&](std::size_t i) { return operand(args.at(i)); };
    if (fn == "sin") return std::sin(arg(0));
    if (fn == "cos") return std::cos(arg(0));
    if (fn == "tan") return std::tan(arg(0));
    if (fn == "atan") return std::atan(arg(0));
    if (fn == "sinh") return std::sinh(arg(0));
    if (fn == "cosh") return std::cosh(arg(0));
    if (fn == "exp") return std::exp(arg(0));
    if (fn == "abs") return std::fabs(arg(0));
    if (fn == "sign") return float((arg(0) > 0) - (arg(0) < 0));
    if (fn == "floor") return std::floor(arg(0));
    if (fn == "ceil") return std::ceil(arg(0));
    if (fn == "min") return std::fmin(arg(0), arg(1));
    if (fn == "max") return std::fmax(arg(0), arg(1));
    if (fn == "zs_atan2") return arg(0) == 0 && arg(1) == 0 ? 0.0f : std::atan2(arg(0), arg(1));
    if (fn == "zs_cbrt") return std::cbrt(arg(0));
    if (fn == "zs_tanh") return std::tanh(std::fmin(std::fmax(arg(0), -10.0f), 10.0f));
    const float a = arg(0);
    if (fn == "zs_sqrt") {
      flag(args.at(1)) |= a < 0;
      return std::sqrt(std::fmax(a, 0.0f));
    }
    if (fn == "zs_log") {
      flag(args.at(1)) |= a < 0;
      return a > 0 ? std::log(a) : -kFltMax;
    }
    if (fn == "zs_asin" || fn == "zs_acos") {
      flag(args.at(1)) |= std::fabs(a) > 1;
      const float c = std::fmin(std::fmax(a, -1.0f), 1.0f);
      return fn == "zs_asin" ? std::asin(c) : std::acos(c);
    }
    const float b = arg(1);
    bool& u = flag(args.at(2));
    if (fn == "zs_div") {
      u |= a == 0 && b == 0;
      return b != 0 ? a / b : (a < 0 ? -kFltMax : kFltMax);
    }
    if (fn == "zs_pow") {
      if (a > 0) return std::pow(a, b);
      if (a == 0) return b > 0 ? 0.0f : (b == 0 ? 1.0f : kFltMax);
      const bool integral = std::floor(b) == b;
      u |= !integral;
      const float m = std::pow(-a, b);
      return integral && std::fmod(std::fabs(b), 2.0f) == 1.0f ? -m : m;
    }
    throw std::runtime_error("unknown function '" + fn + "'");
  }

  // The right-hand sides the emitter writes: an operand, -a, a + b, a - b, a * b * ...,
  // or a call whose arguments are operands.
  float expression(const std::string& e) {
    const auto paren = e.find('(');
    const bool isCall = paren != std::string::npos && paren > 0 && e.back() == ')' &&
                        e.find_first_not_of("abcdefghijklmnopqrstuvwxyz_0123456789") == paren;
    if (isCall) {
      return call(e.substr(0, paren),
                  splitArgs(std::string_view(e).substr(paren + 1, e.size() - paren - 2)));
    }
    if (e[0] == '-' && e.find(' ') == std::string::npos) return -operand(e.substr(1));
    std::vector<std::string> tokens;
    for (std::size_t b = 0, sp; b <= e.size(); b = sp + 1) {
      sp = e.find(' ', b);
      if (sp == std::string::npos) sp = e.size();
      tokens.push_back(e.substr(b, sp - b));
    }
    float acc = operand(tokens[0]);
    for (std::size_t i = 1; i + 1 < tokens.size(); i += 2) {  // left to right, as GLSL
      const float rhs = operand(tokens[i + 1]);
      if (tokens[i] == "+")
        acc = acc + rhs;
      else if (tokens[i] == "-")
        acc = acc - rhs;
      else if (tokens[i] == "*")
        acc = acc * rhs;
      else
        throw std::runtime_error("unknown operator in '" + e + "'");
    }
    return acc;
  }

  // Runs the statements; returns the text of the return statement.
  std::string run(const std::vector<std::string>& body) {
    for (const std::string& s : body) {
      if (s.empty()) continue;
      if (s.rfind("return ", 0) == 0) return s.substr(7, s.size() - 8);
      if (s.rfind("bool ", 0) == 0) {
        flags[s.substr(5, s.find(' ', 5) - 5)] = false;
      } else if (s.rfind("float ", 0) == 0) {
        const auto eq = s.find(" = ");
        vars[s.substr(6, eq - 6)] = expression(s.substr(eq + 3, s.size() - eq - 4));
      } else if (s.size() > 8 && s.substr(s.size() - 8) == " = true;") {
        flag(s.substr(0, s.size() - 8)) = true;
      } else {
        throw std::runtime_error("unknown statement '" + s + "'");
      }
    }
    throw std::runtime_error("no return statement");
  }
};

float finish(float f, bool u) {
  return (u || std::isnan(f)) ? kGlslUndefined : std::fmin(std::fmax(f, -kGlslHuge), kGlslHuge);
}

}  // namespace

FormulaBlockInterpreter::FormulaBlockInterpreter(std::string_view block)
    : fBody_(functionBody(block, "float zs_F(vec3 p)")),
      gradBody_(functionBody(block, "vec4 zs_FGrad(vec3 p)")) {}

float FormulaBlockInterpreter::evalF(const std::array<float, 3>& p,
                                     std::span<const float> params) const {
  Machine m{p, params, {}, {}};
  const std::string ret = m.run(fBody_);  // zs_finishF(F, zs_u)
  const auto args = splitArgs(ret.substr(ret.find('(') + 1, ret.size() - ret.find('(') - 2));
  if (ret.rfind("zs_finishF(", 0) != 0 || args.size() != 2) throw std::runtime_error(ret);
  return finish(m.operand(args[0]), m.flag(args[1]));
}

std::array<float, 4> FormulaBlockInterpreter::evalFGrad(const std::array<float, 3>& p,
                                                        std::span<const float> params) const {
  Machine m{p, params, {}, {}};
  const std::string ret = m.run(gradBody_);  // zs_finishFGrad(vec3(gx, gy, gz), F, u, ug)
  const std::string prefix = "zs_finishFGrad(";
  if (ret.rfind(prefix, 0) != 0) throw std::runtime_error(ret);
  const auto outer =
      splitArgs(std::string_view(ret).substr(prefix.size(), ret.size() - prefix.size() - 1));
  if (outer.size() != 4 || outer[0].rfind("vec3(", 0) != 0) throw std::runtime_error(ret);
  const auto g = splitArgs(std::string_view(outer[0]).substr(5, outer[0].size() - 6));
  if (g.size() != 3) throw std::runtime_error(ret);
  const std::vector<std::string> rest(outer.begin() + 1, outer.end());
  const float f = m.operand(rest[0]);
  if (m.flag(rest[1]) || std::isnan(f)) return {0, 0, 0, kGlslUndefined};
  const float fc = finish(f, false);
  std::array<float, 4> out{m.operand(g[0]), m.operand(g[1]), m.operand(g[2]), fc};
  if (m.flag(rest[2]) || std::isnan(out[0]) || std::isnan(out[1]) || std::isnan(out[2])) {
    return {0, 0, 0, fc};
  }
  for (int i = 0; i < 3; ++i) out[i] = std::fmin(std::fmax(out[i], -kGlslHuge), kGlslHuge);
  return out;
}

}  // namespace zs::test
