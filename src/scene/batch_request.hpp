// The lines of `pita eval --batch FILE` (src/cli/eval_batch.cpp): how the
// file is cut into lines, each bounded in memory, and how a line is read as
// the arguments of one `pita eval`. Apart from the command so that a fuzz
// target (fuzz/fuzz_batch_line.cpp) drives the same code.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace pita::scene {

// One line of the batch without its '\n'. A line longer than
// kMaxBatchLineBytes (scene/limits.hpp) is read to its end but not kept
// (`too_long`, `text` empty), so that memory stays bounded whatever the input.
struct BatchLine {
  std::string text;
  bool too_long = false;
};

// Reads the next line of `file` into `line`; false at the end of the file
// (a last line without '\n' is a line).
bool next_batch_line(std::FILE* file, BatchLine& line);

// The arguments of a request line: a JSON array of strings, none holding a
// NUL character (as no command line can). Throws
// SceneError naming `where` ("batch.txt:3") and the column or the index of
// what is wrong.
std::vector<std::string> batch_request_arguments(std::string_view text, const std::string& where);

}  // namespace pita::scene
