// Microbenchmarks of zeroset's CPU front end, the stages between a typed formula and the
// shader text GL receives: parse, simplify (graph building), symbolic gradient, tape
// compile, GLSL codegen + assembly, glslang validation. Each runs on the 7 thesis surfaces
// (Table 5.1) and Barth's sextic; the benchmark argument is the surface (1..7, 8 = Barth)
// and the label names it. Interval tape evaluation and the octree build are timed in
// zs_bench_interval. Run: build/bench/zs_bench_frontend [--benchmark_filter=parse].
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "app/bench/thesis_data.hpp"
#include "codegen/emit_glsl.hpp"
#include "codegen/glsl_validation.hpp"
#include "codegen/shader_assembly.hpp"
#include "expr/derivative.hpp"
#include "expr/tape.hpp"
#include "parser/parser.hpp"

namespace {

using zs::bench::kThesisSurfaces;

std::string_view formulaText(std::int64_t index) {
  return index <= 7 ? kThesisSurfaces[index - 1].formula : zs::bench::kBarthSextic;
}

std::string label(std::int64_t index) {
  return index <= 7 ? "thesis " + std::to_string(index) : "Barth sextic";
}

// A benchmark input that must parse: a formula that does not is a bug in this file.
zs::Formula parsed(std::int64_t index) {
  zs::ParseResult r = zs::parseFormula(formulaText(index));
  if (auto* f = std::get_if<zs::Formula>(&r)) return std::move(*f);
  std::fprintf(stderr, "bench formula %s does not parse\n", label(index).c_str());
  std::abort();
}

void BM_Parse(benchmark::State& state) {
  const std::string_view text = formulaText(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(zs::parseFormula(text));
  state.SetLabel(label(state.range(0)));
}

// The parser simplifies as it builds (constant folding, x*x -> x^2, hash-consing), so
// "simplify" is the Graph builder alone: the parsed graph replayed node by node through
// constant/var/param/unary/binary/powi into a fresh Graph, without lexing or parsing.
zs::NodeId replay(const zs::Graph& src, zs::Graph& dst) {
  std::vector<zs::NodeId> map(src.size());
  for (std::size_t i = 0; i < src.size(); ++i) {
    const zs::Node& n = src[static_cast<zs::NodeId>(i)];
    const auto a = [&] { return map[static_cast<std::size_t>(n.a)]; };
    switch (n.op) {
      case zs::Op::Const:
        map[i] = dst.constant(n.value);
        break;
      case zs::Op::VarX:
        map[i] = dst.var(0);
        break;
      case zs::Op::VarY:
        map[i] = dst.var(1);
        break;
      case zs::Op::VarZ:
        map[i] = dst.var(2);
        break;
      case zs::Op::Param:
        map[i] = dst.param(src.params()[static_cast<std::size_t>(n.ival)]);
        break;
      case zs::Op::PowI:
        map[i] = dst.powi(a(), n.ival);
        break;
      default:
        map[i] = zs::opInfo(n.op).arity == 1
                     ? dst.unary(n.op, a())
                     : dst.binary(n.op, a(), map[static_cast<std::size_t>(n.b)]);
    }
  }
  return map.empty() ? zs::kNoNode : map.back();
}

void BM_Simplify(benchmark::State& state) {
  const zs::Formula f = parsed(state.range(0));
  for (auto _ : state) {
    zs::Graph g;
    benchmark::DoNotOptimize(replay(f.graph, g));
  }
  state.SetLabel(label(state.range(0)) + ", " + std::to_string(f.graph.size()) + " nodes");
}

// gradient() hash-conses into the graph it is given, so every iteration needs a fresh copy
// of the parsed graph; BM_GraphCopy times that copy alone, to subtract.
void BM_GraphCopy(benchmark::State& state) {
  const zs::Formula f = parsed(state.range(0));
  for (auto _ : state) {
    zs::Graph g = f.graph;
    benchmark::DoNotOptimize(g.size());
  }
  state.SetLabel(label(state.range(0)));
}

void BM_Derivative(benchmark::State& state) {
  const zs::Formula f = parsed(state.range(0));
  std::size_t nodes = 0;
  for (auto _ : state) {
    zs::Graph g = f.graph;
    benchmark::DoNotOptimize(zs::gradient(g, f.root));
    nodes = g.size();
  }
  state.SetLabel(label(state.range(0)) + ", " + std::to_string(nodes) + " nodes with gradient");
}

void BM_TapeCompile(benchmark::State& state) {
  zs::Formula f = parsed(state.range(0));
  const auto grad = zs::gradient(f.graph, f.root);
  const std::vector<zs::NodeId> roots{f.root, grad[0], grad[1], grad[2]};
  std::size_t length = 0;
  for (auto _ : state) {
    zs::Tape tape = zs::compileTape(f.graph, roots);
    length = tape.code.size();
    benchmark::DoNotOptimize(tape);
  }
  state.SetLabel(label(state.range(0)) + ", " + std::to_string(length) + " instructions");
}

// emitFormulaGlsl + assembleFragmentShader: the whole text handed to GL.
void BM_Codegen(benchmark::State& state) {
  zs::Formula f = parsed(state.range(0));
  const auto grad = zs::gradient(f.graph, f.root);
  for (auto _ : state) {
    const zs::GlslFormula glsl = zs::emitFormulaGlsl(f.graph, f.root, grad);
    benchmark::DoNotOptimize(zs::assembleFragmentShader(glsl));
  }
  state.SetLabel(label(state.range(0)));
}

void BM_Glslang(benchmark::State& state) {
  zs::Formula f = parsed(state.range(0));
  const auto grad = zs::gradient(f.graph, f.root);
  const std::string source = zs::assembleFragmentShader(zs::emitFormulaGlsl(f.graph, f.root, grad));
  for (auto _ : state) {
    const zs::ValidationResult r = zs::validateGlsl(source, zs::Stage::Fragment);
    if (!r.ok) {
      state.SkipWithError("glslang rejected a generated shader (a codegen bug)");
      break;
    }
  }
  state.SetLabel(label(state.range(0)) + ", " + std::to_string(source.size()) + " bytes");
}

void surfaces(benchmark::internal::Benchmark* b) {
  for (int i = 1; i <= 8; ++i) b->Arg(i);
}

}  // namespace

BENCHMARK(BM_Parse)->Apply(surfaces);
BENCHMARK(BM_Simplify)->Apply(surfaces);
BENCHMARK(BM_GraphCopy)->Apply(surfaces);
BENCHMARK(BM_Derivative)->Apply(surfaces);
BENCHMARK(BM_TapeCompile)->Apply(surfaces);
BENCHMARK(BM_Codegen)->Apply(surfaces);
BENCHMARK(BM_Glslang)->Apply(surfaces)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
