// Bytes -> pita serve's answer (docs/reference/serve.md "Security"): the
// input is one request as a client sends it, answered by a Service with
// --edit over one scene in a scratch folder, through the request's bounds,
// the Host check, the token check and every route (edits included: they may
// rewrite the scratch scene). Every answer must be a whole HTTP/1.1 answer,
// and every refusal must carry a reason: never an empty 4xx or 5xx (a HEAD
// request's answer has no body, its error included).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "fuzz_support.hpp"
#include "serve/http_request.hpp"
#include "serve/server.hpp"

namespace {

using namespace pita;
namespace fs = std::filesystem;

// The token of the fuzzed server: the seeds and the dictionary carry it.
constexpr const char* kToken = "0123456789abcdef0123456789abcdef";

const char* const kScene = R"({"method": "P2", "keyframes": [
  {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 1, "p": [3, 1], "m": 1.5, "w": 1.2}],
  "claims": [{"measure": "knot-distance", "below": 1e-9, "says": "it interpolates"}]})";

serve::Service& service() {
  static serve::Service* const made = [] {
    const fs::path folder = fuzz::scratch_path("pita-fuzz-http-");
    fs::create_directories(folder);
    std::ofstream(folder / "s.json", std::ios::binary) << kScene;
    serve::Settings settings;
    settings.scenes = {folder / "s.json"};
    settings.token = kToken;
    settings.edit = true;
    auto* s = new serve::Service(settings);
    s->render_all();
    return s;
  }();
  return *made;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view request = fuzz::text_of(data, size);
  const serve::RequestVerdict verdict =
      serve::check_request(request, serve::HttpLimits{}, serve::allowed_hosts("127.0.0.1"));
  PITA_FUZZ_CHECK(verdict.what != serve::RequestVerdict::What::complete || verdict.size <= size);
  PITA_FUZZ_CHECK(verdict.what != serve::RequestVerdict::What::refused || !verdict.reason.empty());

  const std::string answer = service().answer(request);
  PITA_FUZZ_CHECK(answer.rfind("HTTP/1.1 ", 0) == 0 && answer.size() >= 12);
  const int status = std::stoi(answer.substr(9, 3));
  PITA_FUZZ_CHECK(status >= 100 && status < 600);
  const std::size_t head = answer.find("\r\n\r\n");
  PITA_FUZZ_CHECK(head != std::string::npos);
  // A refusal says why (the event stream's answer is 200 with no message
  // here), but to HEAD, whose answers have no body (RFC 9110).
  if (status >= 400 && request.rfind("HEAD ", 0) != 0) PITA_FUZZ_CHECK(answer.size() > head + 4);
  return 0;
}
