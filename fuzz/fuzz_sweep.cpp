// Bytes -> the text surfaces of `pita sweep` (docs/reference/sweep.md "pita
// sweep"): the first line is a --vary argument (POINTER=SPEC: the pointer and
// SPEC parsers, then every value of the axis when it has few); the rest is a
// manifest part as --merge reads it (header, quoted fields, rows in any
// order), streamed, checked for order, sorted, and merged with itself
// refusing conflicts. Bad usage must be a SweepUsageError and a bad manifest
// a std::runtime_error naming the file; nothing else may escape, and a merge
// that succeeds must write its rows in increasing order.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "fuzz_support.hpp"
#include "sweep/grid.hpp"
#include "sweep/manifest.hpp"

namespace {

using namespace pita;
namespace fs = std::filesystem;

const fs::path& work_dir() {
  static const bool made = fs::create_directories(fuzz::scratch_path("pita-fuzz-sweep-")) || true;
  (void)made;
  return fuzz::scratch_path();
}

void axis(std::string_view argument) {
  try {
    const sweep::Axis a = sweep::parse_axis(argument);
    if (a.size() <= 64) {
      for (std::size_t i = 0; i < a.size(); ++i) (void)a.value(i);
    }
  } catch (const sweep::SweepUsageError&) {
  }
}

void manifest(std::string_view text) {
  const fs::path part = work_dir() / "manifest.0-of-1.csv";
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    PITA_FUZZ_CHECK(out.good());
  }
  const std::vector<std::string> pointers = {"/keyframes/1/t"};
  try {
    const bool sorted = sweep::ManifestReader::is_sorted(part, pointers);
    std::vector<sweep::ManifestReader> sources;
    for (int copy = 0; copy < 2; ++copy) {
      auto reader =
          sorted ? sweep::ManifestReader::open(part, pointers) : sweep::ManifestReader::open_sorted(part, pointers);
      PITA_FUZZ_CHECK(reader.has_value());
      sources.push_back(std::move(*reader));
    }
    std::int64_t last = -1;
    sweep::merge_sources(
        work_dir() / "manifest.csv", pointers, sources, [](const sweep::Row&, std::size_t) { return true; },
        [&](const sweep::Row& row) {
          PITA_FUZZ_CHECK(row.index > last);
          last = row.index;
        },
        sweep::SameIndex::refuse_conflict);
  } catch (const std::runtime_error&) {  // the file and line of what is wrong
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::text_of(data, size);
  const std::size_t line = text.find('\n');
  axis(text.substr(0, line));
  if (line != std::string_view::npos) manifest(text.substr(line + 1));
  return 0;
}
