// How a scene file is read: choices of the command line that change what the
// reader accepts (docs/reference/render.md "Figure fields of a scene").
#pragma once

namespace pita::scene {

struct ReadOptions {
  // Images may be given by an absolute path (--allow-absolute-paths). Paths
  // that climb out of the scene's folder ("../x.png", or a symbolic link
  // leading out) are refused either way.
  bool allow_absolute_paths = false;
};

}  // namespace pita::scene
