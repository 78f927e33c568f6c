#include "app/docgen/cli_doc.hpp"

#include <algorithm>

namespace zs::docgen {

namespace {

std::vector<std::string> splitChoices(const std::string& braced) {
  std::vector<std::string> out;
  std::string item;
  for (char c : braced.substr(1, braced.size() - 2)) {
    if (c == ',') {
      out.push_back(item);
      item.clear();
    } else if (c != ' ') {
      item += c;
    }
  }
  if (!item.empty()) out.push_back(item);
  return out;
}

OptionDoc describeOption(const CLI::Option& opt) {
  OptionDoc doc;
  doc.positional = opt.get_positional() && opt.get_snames().empty() && opt.get_lnames().empty();
  if (doc.positional) doc.names.push_back(opt.get_name(true));
  for (const std::string& s : opt.get_snames()) doc.names.push_back("-" + s);
  for (const std::string& l : opt.get_lnames()) doc.names.push_back("--" + l);
  doc.description = opt.get_description();
  doc.required = opt.get_required();
  if (opt.get_items_expected_max() > 0) {
    // "TEXT:{egl,osmesa}" or "INT:INT in [0 - 20]": the type, then each validator's text.
    const std::string full = opt.get_type_name();
    const auto colon = full.find(':');
    doc.value = full.substr(0, colon);
    if (colon != std::string::npos) {
      const std::string rest = full.substr(colon + 1);
      if (rest.size() > 2 && rest.front() == '{' && rest.back() == '}') {
        doc.choices = splitChoices(rest);
      } else {
        doc.constraint = rest;
      }
    }
    doc.count = std::max(1, opt.get_expected_min());
  }
  return doc;
}

CommandDoc describeCommand(CLI::App& app) {
  CommandDoc doc;
  doc.description = app.get_description();
  doc.footer = app.get_footer();
  std::vector<OptionDoc> positionals;
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_group().empty()) continue;  // hidden
    OptionDoc o = describeOption(*opt);
    (o.positional ? positionals : doc.options).push_back(std::move(o));
  }
  doc.options.insert(doc.options.end(), positionals.begin(), positionals.end());
  return doc;
}

}  // namespace

CliDoc describe(CLI::App& app) {
  CliDoc doc;
  doc.top = describeCommand(app);
  doc.top.name = app.get_name();
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    CommandDoc c = describeCommand(*sub);
    c.name = sub->get_name();
    doc.commands.push_back(std::move(c));
  }
  return doc;
}

std::string primaryName(const OptionDoc& option) {
  for (const std::string& n : option.names)
    if (n.starts_with("--")) return n;
  return option.names.front();
}

ValueKind valueKind(const OptionDoc& option) {
  if (option.value.empty() || !option.choices.empty()) return ValueKind::None;
  const std::string name = primaryName(option);
  if (option.positional) return name == "input" ? ValueKind::SceneFile : ValueKind::None;
  if (option.value != "TEXT") return ValueKind::None;  // singular's --depth is a number
  for (const char* file : {"--output", "--depth", "--dump", "--csv", "--json"})
    if (name == file) return ValueKind::File;
  for (const char* dir : {"--out", "--output-dir"})
    if (name == dir) return ValueKind::Directory;
  if (name == "--set") return ValueKind::SceneKey;
  return ValueKind::None;
}

}  // namespace zs::docgen
