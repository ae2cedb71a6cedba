// What defines a sweep (DIR/sweep.json): written by a run, read back by
// --merge to rebuild every variant and check the parts; and the reports both
// write from DIR/manifest.csv.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sweep/grid.hpp"

namespace pita::sweep {

inline constexpr std::string_view kSweepFile = "sweep.json";

// What defines a sweep in DIR (read back by --merge).
struct Definition {
  std::string scene;                                      // the base scene's path, as given
  std::string name;                                       // its stem: the variants' file names
  std::vector<std::pair<std::string, std::string>> axes;  // pointer, spec
  std::vector<std::size_t> axis_sizes;
  bool zip = false;
  std::vector<std::string> formats;
  std::int64_t variants = 0;
  std::string salt;  // what else the content hashes cover (formats, pita's version)
  Json base;         // the base scene's document: --merge rebuilds each variant's hash from it
};

// DIR/sweep.json's text, and the definition read back from it (throws
// SweepUsageError naming the folder when it is missing or not a definition).
std::string definition_json(const Definition& d);
Definition read_definition(const std::filesystem::path& dir);

// The JSON Pointers of the sweep's axes, in order (the manifest's columns).
std::vector<std::string> pointers_of(const Definition& d);

// index.html and contact.* from DIR/manifest.csv (an unsharded run, or a
// merge); what could not be written is added to `notes`.
void write_reports(const std::filesystem::path& dir, const Definition& d, std::vector<std::string>& notes);

}  // namespace pita::sweep
