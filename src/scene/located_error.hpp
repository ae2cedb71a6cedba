// An error about an input that says where and why: the file, the JSON Pointer
// of what is at fault (or a line and column of malformed JSON), and the
// reason. Its three kinds are scene::SceneError (a file pita refuses),
// motion::NoMotion (no motion through the keyframes or poses) and
// render::RenderError (a figure that cannot be drawn); the command line, the
// Python module and pita serve answer each kind from one table,
// kLocatedAnswers, and take the location from this base class.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pita::scene {

enum class LocatedKind { scene, no_motion, render };

class LocatedError : public std::runtime_error {
 public:
  LocatedKind kind() const { return kind_; }
  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }  // "" for the whole document
  const std::string& reason() const { return reason_; }
  int line() const { return line_; }      // 1-based; 0 when the error is not at a position
  int column() const { return column_; }  // 1-based; 0 when the error is not at a position

 protected:
  // what() is located(file, pointer, reason).
  LocatedError(LocatedKind kind, std::string file, std::string pointer, std::string reason);
  // At a position of the text: what() is "FILE:LINE:COLUMN: reason".
  LocatedError(LocatedKind kind, std::string file, int line, int column, std::string reason);

 private:
  LocatedKind kind_;
  std::string file_;
  std::string pointer_;
  std::string reason_;
  int line_ = 0;
  int column_ = 0;
};

// "FILE: POINTER: reason", or "FILE: reason" for the whole document (""): how
// every located error is worded.
std::string located(const std::string& file, const std::string& pointer, const std::string& reason);

// How each front end answers a located error of each kind: pita's exit code
// (docs/reference/exit-codes-and-limits.md; cli/exit_code.hpp names them),
// the Python module's exception class (pita.SceneError, ...; its subclasses:
// python/errors.cpp) and the HTTP status of pita serve's answer, whose body
// is the location as JSON.
struct LocatedAnswer {
  LocatedKind kind;
  int exit_code;
  std::string_view python_class;
  int http_status;
};
inline constexpr std::array<LocatedAnswer, 3> kLocatedAnswers{{
    {LocatedKind::scene, 2, "SceneError", 422},
    {LocatedKind::no_motion, 2, "NoMotionError", 422},
    {LocatedKind::render, 2, "RenderError", 422},
}};

// The row of `kind`.
const LocatedAnswer& answer(LocatedKind kind);

}  // namespace pita::scene
