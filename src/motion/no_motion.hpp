// The one error of the motion stage: no motion exists for these keyframes or
// poses (or it is undefined, or not finite, at a requested time). Like a
// scene error it names the file and the JSON Pointer of what is at fault;
// what() is "FILE: POINTER: reason". The CLI maps it to exit code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace pita::motion {

class NoMotion : public std::runtime_error {
 public:
  NoMotion(std::string file, std::string pointer, std::string reason);

  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  std::string pointer_;
  std::string reason_;
};

}  // namespace pita::motion
