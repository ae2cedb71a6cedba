#include "cli/command_line.hpp"

#include <algorithm>
#include <utility>

#include <CLI/CLI.hpp>

#include "core/methods.hpp"

namespace pita::cli {

namespace {

bool visible(const CLI::Option* option) { return !option->get_group().empty(); }

// The words of "{json,csv}" in CLI11's full type name ("FORMAT:{json,csv}"),
// written there by a CLI::IsMember check.
std::vector<std::string> member_choices(const std::string& type_name) {
  std::vector<std::string> choices;
  const std::size_t open = type_name.find('{');
  const std::size_t close = type_name.find('}', open);
  if (open == std::string::npos || close == std::string::npos) return choices;
  std::string word;
  for (std::size_t i = open + 1; i <= close; ++i) {
    const char c = type_name[i];
    if (c == ',' || c == '}') {
      if (!word.empty()) choices.push_back(word);
      word.clear();
    } else if (c != ' ') {
      word += c;
    }
  }
  return choices;
}

// The formats an option without a check lists in its description after the
// last ':' ("comma-separated: svg,png,pdf (default svg)", "png (default) or
// svg"): its short lowercase words, but for "or", "and" and "default". What
// --help offers is what completion offers.
std::vector<std::string> described_choices(const std::string& description) {
  std::vector<std::string> choices;
  const std::size_t colon = description.rfind(':');
  if (colon == std::string::npos) return choices;
  std::string word;
  const auto flush = [&choices, &word]() {
    const bool short_word = word.size() >= 2 && word.size() <= 4;
    if (short_word && word != "or" && word != "and" &&
        std::find(choices.begin(), choices.end(), word) == choices.end()) {
      choices.push_back(word);
    }
    word.clear();
  };
  for (std::size_t i = colon + 1; i < description.size(); ++i) {
    const char c = description[i];
    if (c >= 'a' && c <= 'z') {
      word += c;
    } else {
      flush();
    }
  }
  flush();
  std::erase(choices, "default");
  return choices;
}

std::string first_sentence(const std::string& description) {
  std::string line = description.substr(0, description.find('\n'));
  const std::size_t stop = line.find(". ");
  if (stop != std::string::npos) line.resize(stop);
  if (!line.empty() && line.back() == '.') line.pop_back();
  return line;
}

OptionModel model_of(const CLI::Option* option) {
  OptionModel model;
  model.positional = !option->nonpositional();
  if (model.positional) {
    model.names.push_back(option->get_name(true));
  } else {
    for (const std::string& name : option->get_snames()) model.names.push_back("-" + name);
    for (const std::string& name : option->get_lnames()) model.names.push_back("--" + name);
  }
  model.first_line = first_sentence(option->get_description());
  model.repeatable = model.positional && option->get_items_expected_max() > 1;
  const std::string type_name = option->get_type_name();
  const std::string value = type_name.substr(0, type_name.find(':'));
  const bool named_method = std::find(model.names.begin(), model.names.end(), "--method") != model.names.end() ||
                            std::find(model.names.begin(), model.names.end(), "--methods") != model.names.end();
  if (option->get_items_expected_max() == 0) {
    model.kind = ValueKind::none;
  } else if (named_method) {
    model.kind = ValueKind::method;
  } else if (!(model.choices = member_choices(type_name)).empty()) {
    model.kind = ValueKind::choice;
  } else if (std::find(model.names.begin(), model.names.end(), "--format") != model.names.end() &&
             !(model.choices = described_choices(option->get_description())).empty()) {
    model.kind = ValueKind::choice;
  } else if (value == "SCENE" || model.names.front() == "SCENE") {
    model.kind = ValueKind::scene;
  } else if (value == "DIR") {
    model.kind = ValueKind::directory;
  } else if (value == "OUT" || value == "FILE" || value == "TABLE") {
    model.kind = ValueKind::file;
  } else {
    model.kind = ValueKind::other;
  }
  return model;
}

SubcommandModel model_of(const CLI::App& app, std::string name) {
  SubcommandModel model;
  model.name = std::move(name);
  model.description = app.get_description();
  for (const CLI::Option* option : app.get_options(visible)) model.options.push_back(model_of(option));
  return model;
}

}  // namespace

std::vector<SubcommandModel> command_line_model(const CLI::App& app) {
  std::vector<SubcommandModel> model{model_of(app, "")};
  for (const CLI::App* subcommand :
       app.get_subcommands([](const CLI::App* sub) { return !sub->get_group().empty(); })) {
    model.push_back(model_of(*subcommand, subcommand->get_name()));
  }
  return model;
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  const auto add = [&names](std::string_view name) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.emplace_back(name);
  };
  for (const MethodEntry& method : every_method()) {
    add(method.id);
    add(method.mnemonic);
  }
  return names;
}

}  // namespace pita::cli
