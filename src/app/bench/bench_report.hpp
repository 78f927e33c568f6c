#pragma once
// Reports of `zeroset bench`: takes the BenchResults of bench_runner.hpp, puts out text.
// The Markdown lays the thesis' Tables 5.2 and 5.3 out as the thesis does (surface, level,
// one column per setting) with our fps beside the published fps, then deeper octree
// levels, the time to first frame per surface and the project's goals marked met or not
// met, the thesis' method (sampling) beside the exact one (bernstein). The CSVs hold
// one row per configuration / per surface, for other tools.
#include <optional>
#include <string>

#include "app/bench/bench_runner.hpp"

namespace zs::bench {

std::string markdownReport(const BenchResults& results);
std::string configCsv(const BenchResults& results);
std::string firstFrameCsv(const BenchResults& results);

// `zeroset bench INPUT`: one table, one row per tracing method, and the ratio.
std::string inputMarkdownReport(const InputBenchResults& results);

// The measured configuration, if it was in the plan (and measured without error).
const ConfigResult* findConfig(const BenchResults& results, const BenchConfig& config);

}  // namespace zs::bench
