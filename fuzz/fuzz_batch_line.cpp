// Bytes -> the requests of `pita eval --batch FILE` (src/cli/eval_batch.cpp):
// the bytes as the batch file, cut into lines by scene::next_batch_line and
// each line read by scene::batch_request_arguments, as the command does
// before it parses the arguments. Checks: as many lines as the file has
// (a '\n' ends each; a last line may lack it), none holding a '\n', none
// kept beyond kMaxBatchLineBytes (a longer one is flagged and empty), and the
// arguments of a request read back the same from their JSON. A bad request
// is a SceneError naming its line; nothing else may escape.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "scene/batch_request.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pita;
  if (size == 0) return 0;  // fmemopen refuses an empty buffer
  std::string bytes(reinterpret_cast<const char*>(data), size);
  std::FILE* file = ::fmemopen(bytes.data(), bytes.size(), "r");
  PITA_FUZZ_CHECK(file != nullptr);
  std::size_t expected = 0;
  for (const char c : bytes) expected += c == '\n' ? 1 : 0;
  if (bytes.back() != '\n') ++expected;
  std::size_t lines = 0;
  scene::BatchLine line;
  while (scene::next_batch_line(file, line)) {
    ++lines;
    PITA_FUZZ_CHECK(line.text.find('\n') == std::string::npos);
    PITA_FUZZ_CHECK(line.text.size() <= scene::kMaxBatchLineBytes);
    if (line.too_long) {
      PITA_FUZZ_CHECK(line.text.empty());
      continue;
    }
    const std::string where = "batch:" + std::to_string(lines);
    try {
      const std::vector<std::string> arguments = scene::batch_request_arguments(line.text, where);
      const std::string again = nlohmann::json(arguments).dump();
      PITA_FUZZ_CHECK(scene::batch_request_arguments(again, where) == arguments);
    } catch (const scene::SceneError& error) {
      PITA_FUZZ_CHECK(std::string(error.what()).find(where) != std::string::npos);
    }
  }
  std::fclose(file);
  PITA_FUZZ_CHECK(lines == expected);
  return 0;
}
