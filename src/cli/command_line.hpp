// The command line as data, read from the CLI11 App that main() builds: the
// subcommands, their options and what each option's value is. The man page
// (cli/man_page.hpp) and the shell completions (cli/completion.hpp) are
// generated from it when pita is built, so they cannot drift from --help.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace pita::cli {

// What an option's value is, for completion.
enum class ValueKind {
  none,       // a flag: no value
  method,     // a method name of the registry (core/methods.hpp)
  choice,     // one of `choices`
  scene,      // a scene file (*.json)
  file,       // any file
  directory,  // a directory
  other,      // a number or a list: nothing to complete
};

struct OptionModel {
  std::vector<std::string> names;  // "-o", "--output"; a positional's name ("SCENE")
  std::string first_line;          // the first sentence of the description
  bool positional = false;
  bool repeatable = false;  // a positional taking several values
  ValueKind kind = ValueKind::none;
  std::vector<std::string> choices;  // kind == choice
};

struct SubcommandModel {
  std::string name;                  // "" for pita itself
  std::string description;           // as --help shows it
  std::vector<OptionModel> options;  // visible options (not the hidden ones), as --help lists them
};

// pita itself first (name ""), then every subcommand in the order --help lists them.
std::vector<SubcommandModel> command_line_model(const CLI::App& app);

// Every method name a scene or --method accepts: ids and mnemonics of
// core/methods.hpp's registry, each once, in registry order.
std::vector<std::string> method_names();

}  // namespace pita::cli
