// How a scene file is read: choices of the command line that change what the
// reader accepts (docs/reference/render.md "Figure fields of a scene").
#pragma once

#include <optional>
#include <string>

namespace pita::scene {

struct ReadOptions {
  // Images may be given by an absolute path (--allow-absolute-paths). Paths
  // that climb out of the scene's folder ("../x.png", or a symbolic link
  // leading out) are refused either way.
  bool allow_absolute_paths = false;
  // The file's "method" replaced by this name before it is read (pita render
  // --method): the scene and every panel without a method of its own draw
  // it, and titles naming {/method} show it.
  std::optional<std::string> method;
};

}  // namespace pita::scene
