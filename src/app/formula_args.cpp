#include "app/formula_args.hpp"

#include <cstdlib>
#include <set>

namespace zs::app {

namespace {

// Every "-x" short option of the app and of its subcommands, at any depth.
void collectShortOptions(CLI::App& app, std::set<std::string>& names) {
  for (const CLI::Option* opt : app.get_options())
    for (const std::string& s : opt->get_snames()) names.insert("-" + s);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    collectShortOptions(*sub, names);
}

bool isNumber(const std::string& s) {
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end && end != s.c_str() && *end == '\0';
}

}  // namespace

void protectMinusFormulas(std::vector<std::string>& args, CLI::App& app) {
  std::set<std::string> shortOptions;
  collectShortOptions(app, shortOptions);
  for (std::size_t i = 1; i < args.size(); ++i) {
    std::string& a = args[i];
    if (a == "--") break;  // the rest is positional already
    if (a.size() < 2 || a[0] != '-' || a[1] == '-') continue;  // not "-...", or a long option
    if (isNumber(a) || shortOptions.count(a)) continue;  // "-1.5" (an option's value), "-o"
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
