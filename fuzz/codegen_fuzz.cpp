// libFuzzer target for the code generator: every formula the parser accepts must yield GLSL
// that glslang accepts (anything else aborts with the internal-error report). Two kinds of
// input, chosen by the low bit of the first byte:
//   even: the remaining bytes are formula text, so coverage guidance explores the whole
//         language, including near-misses the parser rejects;
//   odd:  the next 8 bytes seed the random formula generator (tests/support) and the byte
//         after them picks its depth and parameter count: always-valid formulas, where a
//         parse error is a generator bug and aborts too.
// The shaders validated are the real fragment shaders of every method that applies, as the
// app assembles them: sampling, interval (the affine block zs_FAffine), and Bernstein (the
// ray polynomial) for polynomials up to kMaxBernsteinDegree, constants included. glslang
// takes a few milliseconds per shader, so this target runs some 50-100 inputs a second.
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <variant>

#include "codegen/emit_glsl.hpp"
#include "codegen/emit_interval_glsl.hpp"
#include "codegen/emit_ray_polynomial.hpp"
#include "codegen/glsl_validation.hpp"
#include "codegen/shader_assembly.hpp"
#include "expr/derivative.hpp"
#include "parser/parser.hpp"
#include "render/settings.hpp"
#include "support/random_formula.hpp"

namespace {

// Bounds the work per input: glslang time grows with the formula's size.
constexpr std::size_t kMaxTextBytes = 4096;

std::string fromGenerator(const std::uint8_t* data, std::size_t size) {
  std::uint64_t seed = 0;
  std::memcpy(&seed, data, size < 8 ? size : 8);
  std::mt19937_64 rng(seed);
  zs::test::RandomFormulaOptions options;
  const std::uint8_t knobs = size > 8 ? data[8] : 0;
  options.maxDepth = 1 + knobs % 8;
  options.paramCount = (knobs / 8) % 11;
  return zs::test::randomFormula(rng, options);
}

// Aborts with the internal-error report when glslang rejects `shader`.
void expectValid(const std::string& text, const std::string& what, const std::string& shader) {
  const zs::ValidationResult result = zs::validateGlsl(shader, zs::Stage::Fragment);
  if (result.ok) return;
  std::fprintf(stderr, "formula: %s\n%s\n", text.c_str(),
               zs::formatInternalShaderError(what, result).c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool generated = (data[0] & 1) != 0;
  const std::string text = generated ? fromGenerator(data + 1, size - 1)
                                     : std::string(reinterpret_cast<const char*>(data + 1),
                                                   std::min(size - 1, kMaxTextBytes));
  zs::ParseResult parsed = zs::parseFormula(text);
  if (auto* error = std::get_if<zs::ParseError>(&parsed)) {
    if (!generated) return 0;
    std::fprintf(stderr, "the random formula generator produced an invalid formula:\n%s\n",
                 zs::formatError(text, *error).c_str());
    std::abort();
  }
  zs::Formula& formula = std::get<zs::Formula>(parsed);
  const std::array<zs::NodeId, 3> grad = zs::gradient(formula.graph, formula.root);
  const zs::GlslFormula glsl = zs::emitFormulaGlsl(formula.graph, formula.root, grad);
  expectValid(text, "sampling fragment shader", zs::assembleFragmentShader(glsl));
  expectValid(text, "interval fragment shader",
              zs::assembleFragmentShader(glsl, zs::emitIntervalGlsl(formula.graph, formula.root)));
  // Bernstein where the app uses it: its kernels grow as the degree squared, and above the
  // limit the app traces with the interval method (glslang would take minutes there).
  const std::optional<int> degree = zs::rayPolynomialDegree(formula.graph, formula.root);
  if (degree && *degree <= zs::kMaxBernsteinDegree) {
    const auto poly = zs::emitRayPolynomialGlsl(formula.graph, formula.root);
    expectValid(text, "Bernstein fragment shader", zs::assembleFragmentShader(glsl, *poly));
  }
  return 0;
}
