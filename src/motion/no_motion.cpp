#include "motion/no_motion.hpp"

#include <utility>

namespace pita::motion {

namespace {
std::string located(const std::string& file, const std::string& pointer, const std::string& reason) {
  return pointer.empty() ? file + ": " + reason : file + ": " + pointer + ": " + reason;
}
}  // namespace

NoMotion::NoMotion(std::string file, std::string pointer, std::string reason)
    : std::runtime_error(located(file, pointer, reason)),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      reason_(std::move(reason)) {}

}  // namespace pita::motion
