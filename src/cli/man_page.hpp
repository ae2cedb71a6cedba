// pita.1, the man page: generated when pita is built (`pita --generate man`,
// src/CMakeLists.txt) from the CLI11 App that --help prints, one section per
// subcommand with its usage, description, every option --help lists and its
// footer. Written in the man(7) macros that man-db and groff render.
#pragma once

#include <string>
#include <string_view>

namespace CLI {
class App;
}

namespace pita::cli {

std::string man_page(const CLI::App& app, std::string_view version);

}  // namespace pita::cli
