#include "scene/located_error.hpp"

#include <utility>

#include <fmt/format.h>

namespace pita::scene {

LocatedError::LocatedError(LocatedKind kind, std::string file, std::string pointer, std::string reason)
    : std::runtime_error(located(file, pointer, reason)),
      kind_(kind),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      reason_(std::move(reason)) {}

LocatedError::LocatedError(LocatedKind kind, std::string file, int line, int column, std::string reason)
    : std::runtime_error(fmt::format("{}:{}:{}: {}", file, line, column, reason)),
      kind_(kind),
      file_(std::move(file)),
      reason_(std::move(reason)),
      line_(line),
      column_(column) {}

std::string located(const std::string& file, const std::string& pointer, const std::string& reason) {
  return pointer.empty() ? file + ": " + reason : file + ": " + pointer + ": " + reason;
}

const LocatedAnswer& answer(LocatedKind kind) {
  for (const LocatedAnswer& row : kLocatedAnswers) {
    if (row.kind == kind) return row;
  }
  throw std::logic_error("scene::answer: a located kind without its row in kLocatedAnswers");
}

}  // namespace pita::scene
