#pragma once
// Shared by the codegen tests: formula text -> parsed formula -> GLSL block -> assembled
// fragment shader, with gtest failures (not exceptions) when a step goes wrong.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "codegen/emit_glsl.hpp"
#include "expr/graph.hpp"

namespace zs::test {

// Parses `text` (failing the current test with the caret message if it does not parse).
std::optional<Formula> parseOrFail(std::string_view text);

// Parse + gradient + emit; nothing when the text does not parse.
std::optional<GlslFormula> generate(std::string_view text);

// The repository root: $ZS_SOURCE_DIR, else the path baked in at build time.
std::filesystem::path sourceDir();

std::string readFile(const std::filesystem::path& path);

}  // namespace zs::test
