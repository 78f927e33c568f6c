#pragma once
// A test oracle for the emitter's wiring: takes a generated formula block (emit_glsl.hpp)
// and runs zs_F / zs_FGrad on the CPU in float, with C++ models of the prelude helpers
// (raytrace_prelude.frag.glsl). It understands exactly the statement forms the emitter
// writes and throws std::runtime_error on anything else, so an emitter change that it does
// not know cannot pass silently. Comparing its results with the double-precision tape
// evaluator checks operand order, power chains, gradient components and the undefined flag.
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace zs::test {

inline constexpr float kGlslUndefined = 3.0e38f;  // zs_UNDEFINED in the prelude
inline constexpr float kGlslHuge = 1.0e38f;       // zs_HUGE

class FormulaBlockInterpreter {
 public:
  explicit FormulaBlockInterpreter(std::string_view block);

  float evalF(const std::array<float, 3>& p, std::span<const float> params) const;
  // {gx, gy, gz, F}, as zs_FGrad returns it.
  std::array<float, 4> evalFGrad(const std::array<float, 3>& p,
                                 std::span<const float> params) const;

 private:
  std::vector<std::string> fBody_;
  std::vector<std::string> gradBody_;
};

}  // namespace zs::test
