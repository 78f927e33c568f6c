#pragma once
// A formula may start with a minus sign: `zeroset check "-z^4 + 2*z^3"`. CLI11 would read
// that as an option ("-z") and answer "formula is required". Before parsing, every argument
// that starts with one '-', is not a number and is not one of the command line's own
// options is taken for a formula: it gets a leading space, which CLI11 does not read as an
// option and the formula parser skips. Options keep working anywhere on the line, and "--"
// still ends the options as usual.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace zs::app {

// args[0] is the program name and is left alone.
void protectMinusFormulas(std::vector<std::string>& args, CLI::App& app);

// For the positional FORMULA/INPUT options: takes the protecting space off again, so error
// carets line up with the formula as typed.
void unprotectFormula(CLI::Option& option);

}  // namespace zs::app
