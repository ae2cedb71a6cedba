#include "cli/failure.hpp"

#include <exception>
#include <new>

#include <fmt/format.h>

#include "animate/timeline.hpp"
#include "golden/image_compare.hpp"
#include "io/output_file.hpp"
#include "render/image_cache.hpp"
#include "scene/located_error.hpp"

namespace pita::cli {

std::string printable_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\n' && c != '\t') || u == 0x7f) {
      out += fmt::format("\\x{:02x}", static_cast<unsigned>(u));
    } else {
      out += c;
    }
  }
  return out;
}

namespace {

Failure classify(const std::string& input) {
  try {
    throw;
  } catch (const scene::LocatedError& e) {  // SceneError, NoMotion, RenderError
    return {static_cast<ExitCode>(scene::answer(e.kind()).exit_code), e.what()};
  } catch (const animate::AnimationError& e) {
    return {ExitCode::bad_input, e.what()};
  } catch (const render::ImageError& e) {
    return {ExitCode::bad_input, input + ": " + e.what()};
  } catch (const golden::GoldenError& e) {
    return {ExitCode::bad_input, e.what()};
  } catch (const io::OutputError& e) {
    return {ExitCode::failure, e.what()};
  } catch (const std::bad_alloc&) {
    // Within the render budget a figure needs well under 1 GB: the machine
    // (or a ulimit) has less, or --budget was raised.
    return {ExitCode::bad_input,
            input +
                ": out of memory (the input needs more memory than is available: lower its "
                "sizes (or the --budget of pita render and pita animate), or raise the memory limit)"};
  } catch (const std::exception& e) {
    return {ExitCode::internal_error,
            input + ": internal error, a bug in pita (please report it with this input): " + e.what()};
  } catch (...) {
    return {ExitCode::internal_error, input +
                                          ": internal error, a bug in pita (please report it with this input): an "
                                          "unknown exception"};
  }
}

}  // namespace

Failure current_failure(const std::string& input) {
  Failure failure = classify(input);
  failure.message = printable_text(failure.message);
  return failure;
}

}  // namespace pita::cli
