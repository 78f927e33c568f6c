#include "app/formula_args.hpp"

#include <cstdlib>
#include <map>

namespace zs::app {

namespace {

// Every option name ("-o", "--output") of the app and of its subcommands, at any depth,
// with whether it takes a value.
void collectOptions(CLI::App& app, std::map<std::string, bool>& names) {
  for (const CLI::Option* opt : app.get_options()) {
    const bool takesValue = opt->get_type_size_max() > 0;
    for (const std::string& s : opt->get_snames()) names["-" + s] = takesValue;
    for (const std::string& l : opt->get_lnames()) names["--" + l] = takesValue;
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    collectOptions(*sub, names);
}

bool isNumber(const std::string& s) {
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end && end != s.c_str() && *end == '\0';
}

}  // namespace

void protectMinusFormulas(std::vector<std::string>& args, CLI::App& app) {
  std::map<std::string, bool> options;
  collectOptions(app, options);
  bool valueNext = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    std::string& a = args[i];
    if (a == "--") break;  // the rest is positional already
    const bool isValue = valueNext;
    valueNext = false;
    if (const auto it = options.find(a); it != options.end()) {  // "-o", "--output"
      valueNext = it->second;
      continue;
    }
    if (isValue) continue;  // the value of the option before it: "-o -x.png" stays a file name
    if (a.size() < 2 || a[0] != '-' || a[1] == '-') continue;  // not "-...", or a long option
    if (isNumber(a)) continue;  // "-1.5": a value of an option that takes several
    a.insert(a.begin(), ' ');
  }
}

void unprotectFormula(CLI::Option& option) {
  option.transform(
      [](std::string s) {
        if (s.size() > 1 && s[0] == ' ' && s[1] == '-') s.erase(0, 1);
        return s;
      },
      "", "");
}

}  // namespace zs::app
